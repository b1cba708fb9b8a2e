package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * An agent's animation stopped.
 *
 * @param tick the tick it happened in
 * @param agent the agent
 * @param timeSensor the time sensor or clip
 */
public record AnimationStoppedMessage(long tick,
                                      String agent,
                                      String timeSensor) implements ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AnimationStoppedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.partName(timeSensor, "timeSensor");
    }
}
