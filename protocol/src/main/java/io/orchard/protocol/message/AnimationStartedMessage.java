package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * An agent's animation started: enable its TimeSensor (or play its glTF clip).
 *
 * @param tick the tick it happened in
 * @param agent the agent
 * @param timeSensor the time sensor or clip
 * @param loop whether it repeats
 */
public record AnimationStartedMessage(long tick,
                                      String agent,
                                      String timeSensor,
                                      boolean loop) implements ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AnimationStartedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.partName(timeSensor, "timeSensor");
    }
}
