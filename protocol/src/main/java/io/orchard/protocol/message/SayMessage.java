package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * An agent speaking back to people: answers, questions, reports. The server relays it to every
 * viewer and client, and viewers show it.
 *
 * @param seq the sender's sequence number
 * @param agent the agent that speaks
 * @param text what it says
 */
public record SayMessage(long seq,
                         String agent,
                         String text) implements ClientMessage, ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public SayMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.text(text, "text");
    }
}
