package io.orchard.viewer.world;

/**
 * One line of what happened, for people: something an agent said, an agent coming or going, a
 * fruit eaten, the game starting or ending, a refusal from the server, a model that failed.
 *
 * @param time the simulated time it happened
 * @param kind what sort of line it is, so that a display can colour it
 * @param text the line itself
 */
public record LogLine(double time, Kind kind, String text) {

    /** What sort of line it is. */
    public enum Kind {
        /** An agent spoke ({@code Say}). */
        SAY,
        /** Something happened in the game. */
        EVENT,
        /** Something went wrong: a server refusal, a model that could not be shown. */
        PROBLEM
    }
}
