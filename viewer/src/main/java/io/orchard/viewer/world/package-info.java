/**
 * The world as the viewer knows it, with no graphics: what the server has told it (the static
 * world of the snapshot, the fruit left, the agents with their moves, headings, joints and running
 * animations, the scores, what was said) and what can be computed from that (where an agent stands
 * at a given simulated time, what it perceives). The scene is drawn from this model, never the
 * other way round, so every rule here is tested without a GL context.
 *
 * <p>A {@link io.orchard.viewer.world.WorldMirror} is used from one thread only: the viewer's
 * render thread. Other threads hand messages to that thread; they never touch the mirror.
 */
package io.orchard.viewer.world;
