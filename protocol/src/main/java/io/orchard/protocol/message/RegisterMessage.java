package io.orchard.protocol.message;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;

/**
 * Registers an agent in the environment (the paper's RegisterMessage). The agent's model must
 * contain a Transform named after the agent. The server answers with {@link RegisteredMessage},
 * carrying the body in force and where the agent was placed, or with an {@link ErrorMessage}.
 *
 * @param seq client-chosen sequence number
 * @param name the agent's unique name
 * @param body the body the agent asks for; the server caps it at its limits
 * @param model the agent's visual model; viewers show a placeholder without one
 * @param resumeToken the token of an earlier registration of this name (from its
 *                    {@link RegisteredMessage}), to get that agent back after a reconnection or a
 *                    server restart: its place, heading, body and score; null for a new agent
 */
public record RegisterMessage(long seq,
                              String name,
                              Body body,
                              @Nullable ModelSpec model,
                              @Nullable String resumeToken) implements ClientMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RegisterMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(name, "name");
        Checks.present(body, "body");
        Checks.optionalText(resumeToken, "resumeToken");
    }

    /** A registration of a new agent, without a resume token. */
    public RegisterMessage(long seq, String name, Body body, @Nullable ModelSpec model) {
        this(seq, name, body, model, null);
    }
}
