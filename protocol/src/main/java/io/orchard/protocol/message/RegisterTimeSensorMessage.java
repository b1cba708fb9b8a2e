package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Registers a TimeSensor node of the agent's model, so that {@link StartAnimationMessage} and
 * {@link StopAnimationMessage} may start and stop the animation it drives.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param timeSensor the TimeSensor's name in the model (or a glTF clip's name)
 */
public record RegisterTimeSensorMessage(long seq,
                                        String agent,
                                        String timeSensor) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RegisterTimeSensorMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.partName(timeSensor, "timeSensor");
    }
}
