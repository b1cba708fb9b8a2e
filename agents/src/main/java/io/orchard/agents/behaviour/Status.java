package io.orchard.agents.behaviour;

/** How a behaviour stands after a tick's step. */
public enum Status {
    /** Still at it. */
    RUNNING,
    /** Finished: arrived, collected. */
    DONE,
    /** Gave up: no way there, the fruit is gone or out of reach. */
    FAILED
}
