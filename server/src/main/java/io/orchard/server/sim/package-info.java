/**
 * The simulation: the clock, the agents in the world, their actions, perception, grasps, the game
 * and its scores. It knows no sockets: clients are {@link io.orchard.server.sim.ClientSession}s and
 * what they do arrives through the {@link io.orchard.server.sim.Inbox}, so tests step it tick by tick
 * with plain objects. One thread owns it; see {@link io.orchard.server.sim.TickLoop}, which also
 * measures how long ticks take ({@link io.orchard.server.sim.TickStats}) and keeps its time on a
 * clock that tests replace. A whole game can be saved at the end of a tick and continued later
 * ({@link io.orchard.server.sim.Checkpoint}, {@link io.orchard.server.sim.CheckpointFile}).
 *
 * <p>{@link io.orchard.server.sim.Simulation} owns the parts and hands each its share; none of them
 * knows it. Everything said goes through the outbox (sessions, recording, the current tick and
 * time); agents register and leave through the registrations (names, resume tokens, where and in what
 * order agents enter); every other message about an agent is an action; the game keeps the phase.
 * The order in which a tick's messages are applied is the event order's; in lockstep, whose turn a
 * tick waits for, and who missed theirs, is the turns'. A lockstep game played again by the same
 * agents gives the same record, byte for byte: see {@link io.orchard.server.sim.Recorder} and
 * {@link io.orchard.server.sim.MissedTurn}.
 */
package io.orchard.server.sim;
