package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Removes the agent from the environment. Its score stays in the game's ranking.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 */
public record UnregisterMessage(long seq,
                                String agent) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public UnregisterMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
    }
}
