package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Rotation;

/**
 * Changes the agent's orientation in the world: a rotation about the up axis, which sets its heading.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param rotation the new orientation, about (0, 1, 0)
 */
public record SetRotationMessage(long seq,
                                 String agent,
                                 Rotation rotation) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public SetRotationMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.present(rotation, "rotation");
    }
}
