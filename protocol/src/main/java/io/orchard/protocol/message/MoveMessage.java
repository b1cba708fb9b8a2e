package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Vec3;

/**
 * Moves the agent from one point to another on the ground. The agent walks the segment at its top
 * speed; the server rejects the move, naming the obstacle, when {@code from} is given and is more
 * than {@link #FROM_TOLERANCE} units from where the agent is, or when the path crosses a tree, a
 * table, the castle, the river away from a bridge or the world's edge, and stops it at contact when
 * another agent is in the way. Without {@code from} the agent walks from wherever it is when the
 * server applies the move, which in realtime may be some ticks after the perception it was planned on.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param from where the agent is now (its y is ignored); optional
 * @param to where it should go (its y is ignored)
 */
public record MoveMessage(long seq,
                          String agent,
                          @Nullable Vec3 from,
                          Vec3 to) implements ClientMessage, AgentMessage {

    /** How far, on the ground, {@code from} may be from where the server has the agent: 0.5 units. */
    public static final double FROM_TOLERANCE = 0.5;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public MoveMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.present(to, "to");
    }

    /** A move from wherever the agent is when the server applies it. */
    public MoveMessage(long seq, String agent, Vec3 to) {
        this(seq, agent, null, to);
    }
}
