package io.orchard.viewer.world;

import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import java.util.List;

/**
 * What one agent perceives at one moment, as the viewer works it out from what it knows: the
 * trees and tables, the other agents and the fruit inside its view cone, within range and not
 * behind the castle.
 *
 * @param objects trees and tables in view
 * @param agents  other agents in view
 * @param fruit   fruit in view
 */
public record Sighting(List<Obstacle> objects, List<AgentView> agents, List<FruitState> fruit) {

    /** Keeps its own unmodifiable copy of the lists. */
    public Sighting {
        objects = List.copyOf(objects);
        agents = List.copyOf(agents);
        fruit = List.copyOf(fruit);
    }

    /** Nothing in view. */
    public static final Sighting NOTHING = new Sighting(List.of(), List.of(), List.of());

    /** How many things are in view. */
    public int size() {
        return objects.size() + agents.size() + fruit.size();
    }
}
