package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Sector;

/**
 * The castle, perceived only vaguely: the compass sector it lies in as seen from the agent.
 *
 * @param tick the tick it was computed in
 * @param agent the perceiving agent
 * @param sector "north", "south-west"...
 */
public record CastlePerceptionMessage(long tick,
                                      String agent,
                                      Sector sector) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public CastlePerceptionMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.present(sector, "sector");
    }
}
