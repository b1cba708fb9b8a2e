package io.orchard.agents.zoo;

import io.orchard.agents.AgentController;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.Function;

/** The paper's five agents, by name: what {@code ./orchard agent --type} chooses from. */
public enum Species {
    /** {@link Dwarf}: subsumption layers. */
    DWARF(Dwarf::new),
    /** {@link Robot}: map building with a planner. */
    ROBOT(Robot::new),
    /** {@link Bunny}: purely reactive. */
    BUNNY(Bunny::new),
    /** {@link Guppy}: a goal stack. */
    GUPPY(Guppy::new),
    /** {@link Roadrunner}: a behaviour-based arbiter with utility scores. */
    ROADRUNNER(Roadrunner::new);

    private final Function<String, AgentController> maker;

    Species(Function<String, AgentController> maker) {
        this.maker = maker;
    }

    /** The species' own name, as its model names its root: "Dwarf", "Roadrunner". */
    public String agentName() {
        String lower = name().toLowerCase(Locale.ROOT);
        return Character.toUpperCase(lower.charAt(0)) + lower.substring(1);
    }

    /** A new agent of this species called {@code name}. */
    public AgentController create(String name) {
        return maker.apply(name);
    }

    /** A new agent of this species under its own name. */
    public AgentController create() {
        return create(agentName());
    }

    /**
     * The species of this name, ignoring case.
     *
     * @throws IllegalArgumentException naming the word and the species known
     */
    public static Species named(String word) {
        for (Species species : values()) {
            if (species.name().equalsIgnoreCase(word.strip())) {
                return species;
            }
        }
        throw new IllegalArgumentException("no agent type '" + word + "'; expected one of "
                + String.join(", ", Arrays.stream(values()).map(s -> s.name().toLowerCase(Locale.ROOT)).toList()));
    }
}
