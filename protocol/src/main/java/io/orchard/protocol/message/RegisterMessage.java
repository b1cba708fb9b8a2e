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
 */
public record RegisterMessage(long seq,
                              String name,
                              Body body,
                              @Nullable ModelSpec model) implements ClientMessage {

    public RegisterMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(name, "name");
        Checks.present(body, "body");
    }
}
