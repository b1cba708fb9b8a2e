package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;

/**
 * A person's instruction in simple English ("pick up the banana on the table") for one agent. Any
 * client may send it; the server routes it to the controller of the named agent, unchanged.
 *
 * @param seq the sender's sequence number
 * @param agent the agent that should act on it
 * @param text the instruction
 * @param from who gives it, for the agent's answer
 */
public record InstructionMessage(long seq,
                                 String agent,
                                 String text,
                                 @Nullable String from) implements ClientMessage, ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public InstructionMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.text(text, "text");
        Checks.optionalText(from, "from");
    }
}
