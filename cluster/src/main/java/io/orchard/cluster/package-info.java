/**
 * One world served by a cluster of servers: the world cut into parcels, each simulated on its own
 * with the single server's rules ({@link io.orchard.server.sim.PartialSimulation}), and what they
 * say put in the single server's order. See docs/scaling.md.
 */
package io.orchard.cluster;
