package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Stops an agent-specific animation (disables its TimeSensor).
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param timeSensor a registered time sensor
 */
public record StopAnimationMessage(long seq,
                                   String agent,
                                   String timeSensor) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public StopAnimationMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.partName(timeSensor, "timeSensor");
    }
}
