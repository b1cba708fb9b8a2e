/**
 * The simulation: the clock, the agents in the world, their actions, perception, grasps, the game
 * and its scores. It knows no sockets: clients are {@link io.orchard.server.sim.ClientSession}s and
 * what they do arrives through the {@link io.orchard.server.sim.Inbox}, so tests step it tick by tick
 * with plain objects. One thread owns it; see {@link io.orchard.server.sim.TickLoop}, which also
 * measures how long ticks take ({@link io.orchard.server.sim.TickStats}). A whole game can be saved
 * at the end of a tick and continued later ({@link io.orchard.server.sim.Checkpoint},
 * {@link io.orchard.server.sim.CheckpointFile}).
 */
package io.orchard.server.sim;
