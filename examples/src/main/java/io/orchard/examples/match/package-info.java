/**
 * What the demo and the tournament share: a line-up of agents named on the command line, agents
 * played on threads of this JVM against a server, and the ranking printed as a table.
 */
package io.orchard.examples.match;
