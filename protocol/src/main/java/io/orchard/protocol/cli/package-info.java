/**
 * Command-line options shared by Orchard's programs (the server, the viewer, the agents), so that
 * every program reads its options, prints its help and reports a bad option the same way.
 */
package io.orchard.protocol.cli;
