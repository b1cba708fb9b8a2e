package io.orchard.viewer.state;

/**
 * The scene's clock: the simulated time, in seconds, that the scene shows this frame. A live
 * server's clock follows its ticks; a replay's follows the recording, never the wall clock, which
 * is what makes screenshots of a recording repeatable.
 */
public interface SimClock {

    /** The simulated time to show, never decreasing from one frame to the next except on a seek. */
    double now();
}
