package io.orchard.server.sim;

import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Agents bucketed by where they stand, so that "who is near here?" costs the agents nearby rather
 * than every agent. Built from the agents' positions at one moment; {@link #move} keeps it true
 * while agents walk.
 */
final class AgentGrid {

    private final double cell;
    private final Map<Long, List<Agent>> cells = new HashMap<>();

    AgentGrid(Iterable<Agent> agents, double cell) {
        this.cell = cell;
        for (Agent agent : agents) {
            cells.computeIfAbsent(key(index(agent.position.x()), index(agent.position.z())), k -> new ArrayList<>())
                    .add(agent);
        }
    }

    /** Moves an agent's entry from where it stands to {@code to}; the caller then updates its position. */
    void move(Agent agent, Vec3 to) {
        long from = key(index(agent.position.x()), index(agent.position.z()));
        long next = key(index(to.x()), index(to.z()));
        if (from != next) {
            cells.get(from).remove(agent);
            cells.computeIfAbsent(next, k -> new ArrayList<>()).add(agent);
        }
    }

    /** Calls {@code action} for every agent whose centre may be within {@code range} of {@code at}. */
    void forEachWithin(Vec3 at, double range, Consumer<Agent> action) {
        int x0 = index(at.x() - range);
        int x1 = index(at.x() + range);
        int z0 = index(at.z() - range);
        int z1 = index(at.z() + range);
        for (int x = x0; x <= x1; x++) {
            for (int z = z0; z <= z1; z++) {
                List<Agent> here = cells.get(key(x, z));
                if (here != null) {
                    here.forEach(action);
                }
            }
        }
    }

    private int index(double coordinate) {
        return (int) Math.floor(coordinate / cell);
    }

    /** A unique key per cell whose hash spreads well: neighbouring and mirrored cells do not collide. */
    private static long key(int x, int z) {
        return x * 0x9E3779B1L + z;
    }
}
