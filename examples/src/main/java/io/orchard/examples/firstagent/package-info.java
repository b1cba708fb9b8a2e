/**
 * The smallest useful agent a student writes, {@link io.orchard.examples.firstagent.FirstAgent}, and
 * {@code ./orchard first-agent}, which plays it against a server; docs/tutorial.md walks through both.
 */
package io.orchard.examples.firstagent;
