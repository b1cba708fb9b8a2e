package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;

/**
 * The answer to {@link GraspRequestMessage}: whether the agent got the fruit and, if not, why.
 *
 * @param seq the grasp request's sequence number
 * @param agent the agent that grasped
 * @param fruit the fruit's id
 * @param success whether the fruit is the agent's
 * @param reason why not ("fruit F3 is 2.4 units away, reach is 1.2")
 * @param points points scored, 0 on failure
 */
public record GraspResultMessage(long seq,
                                 String agent,
                                 String fruit,
                                 boolean success,
                                 @Nullable String reason,
                                 int points) implements ServerMessage, Reply {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GraspResultMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.id(fruit, "fruit");
        Checks.optionalText(reason, "reason");
        Checks.nonNegative(points, "points");
    }
}
