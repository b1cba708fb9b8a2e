package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Registers a Transform node of the agent's model as a joint, so that
 * {@link SetJointRotationMessage} may drive it.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param joint the Transform's name in the model
 */
public record RegisterJointMessage(long seq,
                                   String agent,
                                   String joint) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RegisterJointMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.partName(joint, "joint");
    }
}
