package io.orchard.agents.language;

import java.util.Objects;

/**
 * Follow another agent, keeping a short distance behind it: "follow Roadrunner", "go after the
 * robot", "follow the nearest agent". Following lasts until a new instruction or until the agent
 * has lost sight of the other for long.
 *
 * @param agent the agent to follow: {@link Reference.Kind#AGENT}, by name or by distance
 */
public record Follow(Reference agent) implements Goal {

    /** @throws IllegalArgumentException when the reference is not to an agent */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Follow {
        Objects.requireNonNull(agent, "agent");
        if (agent.kind() != Reference.Kind.AGENT) {
            throw new IllegalArgumentException("only an agent can be followed, not " + agent.kind());
        }
    }

    /** Follow the agent with this name. */
    public static Follow agent(String name) {
        return new Follow(Reference.agent(name));
    }
}
