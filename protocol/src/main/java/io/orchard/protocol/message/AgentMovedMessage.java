package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Vec3;

/**
 * An agent moves from one point to another, starting at {@code startTime} and taking
 * {@code duration} simulated seconds: viewers interpolate, as the paper's PositionInterpolator and
 * TimeSensor did.
 *
 * @param tick the tick the move was accepted in
 * @param agent the agent
 * @param from the start
 * @param to the end
 * @param startTime simulated time at the start
 * @param duration simulated seconds the move takes
 */
public record AgentMovedMessage(long tick,
                                String agent,
                                Vec3 from,
                                Vec3 to,
                                double startTime,
                                double duration) implements ServerMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentMovedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.present(from, "from");
        Checks.present(to, "to");
        Checks.nonNegative(startTime, "startTime");
        Checks.nonNegative(duration, "duration");
    }
}
