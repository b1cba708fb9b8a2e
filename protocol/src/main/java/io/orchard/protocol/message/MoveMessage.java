package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Vec3;

/**
 * Moves the agent from one point to another on the ground. The agent walks the segment at its top
 * speed; the server rejects the move, naming the obstacle, when {@code from} is not where the agent
 * is or the path crosses a tree, a table, the castle, the river away from a bridge or the world's
 * edge, and stops it at contact when another agent is in the way.
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param from where the agent is now (its y is ignored)
 * @param to where it should go (its y is ignored)
 */
public record MoveMessage(long seq,
                          String agent,
                          Vec3 from,
                          Vec3 to) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public MoveMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.present(from, "from");
        Checks.present(to, "to");
    }
}
