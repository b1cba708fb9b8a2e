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
 * @param seed the agent's own seed (version 2), derived by the server from the game's seed and the
 *             agent's name: an agent that draws its random numbers from it plays the same game
 *             again in lockstep. It is not the world's seed, which would give the world away
 */
public record RegisteredMessage(long seq,
                                String agent,
                                Body body,
                                Vec3 position,
                                double heading,
                                @Nullable String resumeToken,
                                @Nullable Long seed) implements ServerMessage, Reply {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RegisteredMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.present(body, "body");
        Checks.present(position, "position");
        Checks.finite(heading, "heading");
        Checks.optionalText(resumeToken, "resumeToken");
    }

    /** An answer without a resume token and without a seed. */
    public RegisteredMessage(long seq, String agent, Body body, Vec3 position, double heading) {
        this(seq, agent, body, position, heading, null, null);
    }

    /** An answer without a seed, as version 1 clients get it. */
    public RegisteredMessage(long seq, String agent, Body body, Vec3 position, double heading, String resumeToken) {
        this(seq, agent, body, position, heading, resumeToken, null);
    }

    /** The same answer without the agent's seed, for a client of protocol version 1. */
    public RegisteredMessage withoutSeed() {
        return seed == null ? this : new RegisteredMessage(seq, agent, body, position, heading, resumeToken, null);
    }
}
