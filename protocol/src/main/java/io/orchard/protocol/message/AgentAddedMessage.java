package io.orchard.protocol.message;

import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Checks;

/**
 * An agent entered the world, with its model for viewers to load.
 *
 * @param tick the tick it happened in
 * @param agent the agent
 */
public record AgentAddedMessage(long tick,
                                AgentState agent) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentAddedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.present(agent, "agent");
    }
}
