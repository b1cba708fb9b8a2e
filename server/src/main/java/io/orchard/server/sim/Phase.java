package io.orchard.server.sim;

/** Where a game is in its life. */
public enum Phase {
    /** Waiting for agents (or a start command); no ticks pass. */
    WAITING,
    /** Ticks pass. */
    RUNNING,
    /** Paused by a command; no ticks pass. */
    PAUSED,
    /** The fruit is gone or the time is up. */
    OVER
}
