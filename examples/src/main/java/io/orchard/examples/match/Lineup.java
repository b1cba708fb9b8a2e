package io.orchard.examples.match;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The agents of a game, by name: the paper's five ({@code Dwarf}, {@code Robot}, {@code Bunny},
 * {@code Guppy}, {@code Roadrunner}) and others the caller names, such as the tutorial's
 * {@code FirstAgent}. A line-up makes new agents for every game, since an agent plays one game.
 */
public final class Lineup {

    private final List<String> names;
    private final List<Supplier<AgentController>> makers;

    private Lineup(List<String> names, List<Supplier<AgentController>> makers) {
        this.names = List.copyOf(names);
        this.makers = List.copyOf(makers);
    }

    /** The paper's five agents. */
    public static Lineup zoo() {
        return parse(String.join(",", Arrays.stream(Species.values()).map(Species::agentName).toList()), Map.of());
    }

    /**
     * The agents named in a comma-separated list, such as {@code Dwarf,Robot,FirstAgent} (any case):
     * the paper's five, and the agents of {@code others} by their names.
     *
     * @throws IllegalArgumentException naming an unknown or repeated agent, or an empty name
     */
    public static Lineup parse(String list, Map<String, Supplier<AgentController>> others) {
        List<String> names = new ArrayList<>();
        List<Supplier<AgentController>> makers = new ArrayList<>();
        Set<String> seen = new LinkedHashSet<>();
        for (String word : list.split(",", -1)) {
            String name = word.strip();
            if (name.isEmpty()) {
                throw new IllegalArgumentException("'" + list + "' has an empty name (expected agents separated by "
                        + "commas, such as Dwarf,Robot)");
            }
            if (!seen.add(name.toLowerCase(Locale.ROOT))) {
                throw new IllegalArgumentException("'" + list + "' names " + name
                        + " twice (expected each agent once: an agent plays once per game)");
            }
            String other = others.keySet().stream().filter(name::equalsIgnoreCase).findFirst().orElse(null);
            if (other != null) {
                names.add(other);
                makers.add(others.get(other));
            } else {
                Species species = species(name, others.keySet());
                names.add(species.agentName());
                makers.add(species::create);
            }
        }
        return new Lineup(names, makers);
    }

    /** The agents' names, in the order given. */
    public List<String> names() {
        return names;
    }

    /** New agents for one game. */
    public List<AgentController> create() {
        return makers.stream().map(Supplier::get).toList();
    }

    private static Species species(String name, Set<String> others) {
        for (Species species : Species.values()) {
            if (species.agentName().equalsIgnoreCase(name)) {
                return species;
            }
        }
        List<String> known = new ArrayList<>(Arrays.stream(Species.values()).map(Species::agentName).toList());
        others.stream().sorted().forEach(known::add);
        throw new IllegalArgumentException("no agent '" + name + "' (expected some of " + String.join(", ", known)
                + ")");
    }
}
