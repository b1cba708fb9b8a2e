package io.orchard.protocol.message;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Vec3;

/**
 * The answer to {@link RegisterMessage}: the agent is in the world, with the body in force (capped
 * at the server's limits) at the place the server chose.
 *
 * @param seq the registration's sequence number
 * @param agent the agent's name
 * @param body the body in force
 * @param position where the agent stands
 * @param heading its heading in radians
 * @param resumeToken a secret that gets this agent back when its controller registers the same
 *                    name with it after a dropped connection or a server restart; keep it private
 */
public record RegisteredMessage(long seq,
                                String agent,
                                Body body,
                                Vec3 position,
                                double heading,
                                @Nullable String resumeToken) implements ServerMessage, Reply {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RegisteredMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.present(body, "body");
        Checks.present(position, "position");
        Checks.finite(heading, "heading");
        Checks.optionalText(resumeToken, "resumeToken");
    }

    /** An answer without a resume token. */
    public RegisteredMessage(long seq, String agent, Body body, Vec3 position, double heading) {
        this(seq, agent, body, position, heading, null);
    }
}
