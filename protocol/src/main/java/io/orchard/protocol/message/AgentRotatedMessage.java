package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Rotation;

/**
 * An agent's orientation changed.
 *
 * @param tick the tick it happened in
 * @param agent the agent
 * @param rotation its new orientation
 */
public record AgentRotatedMessage(long tick,
                                  String agent,
                                  Rotation rotation) implements ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentRotatedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.present(rotation, "rotation");
    }
}
