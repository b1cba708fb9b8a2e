package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Sent when the agent thinks it has grasped a fruit. If the server decides the grasp succeeds, the
 * fruit is removed from the world, the agent scores and every agent hears {@link FruitEatenMessage};
 * either way the agent gets a {@link GraspResultMessage}.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param fruit the id of the fruit, as perceived
 */
public record GraspRequestMessage(long seq,
                                  String agent,
                                  String fruit) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GraspRequestMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.id(fruit, "fruit");
    }
}
