package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * The simulation clock: sent to every client at the start of each tick.
 *
 * @param tick the tick that starts
 * @param time simulated seconds since the game started
 */
public record TickMessage(long tick,
                          double time) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public TickMessage {
        Checks.nonNegative(tick, "tick");
        Checks.nonNegative(time, "time");
    }
}
