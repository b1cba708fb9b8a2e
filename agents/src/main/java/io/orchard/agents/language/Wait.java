package io.orchard.agents.language;

/**
 * Stay where it is, for a while or until the next instruction: "wait here", "stay", "hold on",
 * "wait 10 seconds". Unlike {@link Stop}, a wait with a duration ends by itself: the agent goes on
 * with the next step of a {@link Sequence}, or returns to autonomy.
 *
 * @param seconds how long to wait, in simulated seconds; {@link #UNTIL_TOLD} for no limit
 */
public record Wait(double seconds) implements Goal {

    /** The duration of a wait that lasts until the next instruction. */
    public static final double UNTIL_TOLD = Double.POSITIVE_INFINITY;

    /** @throws IllegalArgumentException when {@code seconds} is negative or NaN */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Wait {
        if (!(seconds >= 0)) {
            throw new IllegalArgumentException("seconds must be at least 0 (or UNTIL_TOLD), was " + seconds);
        }
    }

    /** A wait until the next instruction. */
    public static Wait untilTold() {
        return new Wait(UNTIL_TOLD);
    }

    /** Whether this wait lasts until the next instruction. */
    public boolean isUntilTold() {
        return seconds == UNTIL_TOLD;
    }
}
