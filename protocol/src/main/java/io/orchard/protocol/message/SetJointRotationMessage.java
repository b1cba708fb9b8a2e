package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Rotation;

/**
 * Changes the orientation of a registered joint of the agent's body model.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param joint a joint registered with {@link RegisterJointMessage}
 * @param rotation the joint's new rotation, relative to its parent
 */
public record SetJointRotationMessage(long seq,
                                      String agent,
                                      String joint,
                                      Rotation rotation) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public SetJointRotationMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.partName(joint, "joint");
        Checks.present(rotation, "rotation");
    }
}
