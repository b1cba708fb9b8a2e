package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * An agent left the world: it unregistered or its connection dropped.
 *
 * @param tick the tick it happened in
 * @param agent the agent
 * @param reason why
 */
public record AgentRemovedMessage(long tick,
                                  String agent,
                                  String reason) implements ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentRemovedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.text(reason, "reason");
    }
}
