package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedRiver;

import java.util.List;

/**
 * The position of the landmarks, the river and the two bridges, relative to the agent.
 *
 * @param tick the tick it was computed in
 * @param agent the perceiving agent
 * @param river the river, when in view
 * @param bridges bridges in view
 */
public record LandmarkPerceptionMessage(long tick,
                                        String agent,
                                        @Nullable PerceivedRiver river,
                                        List<PerceivedBridge> bridges) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LandmarkPerceptionMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        bridges = Checks.list(bridges, "bridges");
    }
}
