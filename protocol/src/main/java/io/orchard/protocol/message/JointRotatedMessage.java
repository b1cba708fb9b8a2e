package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Rotation;

/**
 * A registered joint of an agent's model turned.
 *
 * @param tick the tick it happened in
 * @param agent the agent
 * @param joint the joint's Transform
 * @param rotation its new rotation
 */
public record JointRotatedMessage(long tick,
                                  String agent,
                                  String joint,
                                  Rotation rotation) implements ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public JointRotatedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.partName(joint, "joint");
        Checks.present(rotation, "rotation");
    }
}
