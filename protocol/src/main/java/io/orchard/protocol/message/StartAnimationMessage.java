package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Starts an agent-specific animation: enables a registered TimeSensor, for example to walk or to grasp.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param timeSensor a time sensor registered with {@link RegisterTimeSensorMessage}
 * @param loop whether the animation repeats until stopped
 */
public record StartAnimationMessage(long seq,
                                    String agent,
                                    String timeSensor,
                                    boolean loop) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public StartAnimationMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.partName(timeSensor, "timeSensor");
    }
}
