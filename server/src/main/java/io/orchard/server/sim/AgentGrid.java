package io.orchard.server.sim;

import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;

/**
 * Agents bucketed by where they stand, so that "who is near here?" costs the agents nearby rather
 * than every agent. Built from the agents' positions at one moment; {@link #move} keeps it true
 * while agents walk.
 *
 * <p>The cells that hold agents are found through an open-addressing table keyed by the cell's
 * coordinates packed in a long: a query visits many cells, most of them empty, and a lookup must
 * not box its key.
 */
final class AgentGrid {

    private static final long EMPTY = Long.MIN_VALUE;

    private final double cell;
    private long[] keys;
    private List<Agent>[] lists;
    private int used;

    AgentGrid(Iterable<Agent> agents, double cell) {
        this.cell = cell;
        allocate(64);
        for (Agent agent : agents) {
            listAt(key(index(agent.position.x()), index(agent.position.z())), true).add(agent);
        }
    }

    /** Moves an agent's entry from where it stands to {@code to}; the caller then updates its position. */
    void move(Agent agent, Vec3 to) {
        long from = key(index(agent.position.x()), index(agent.position.z()));
        long next = key(index(to.x()), index(to.z()));
        if (from != next) {
            listAt(from, false).remove(agent);
            listAt(next, true).add(agent);
        }
    }

    /** Calls {@code action} for every agent whose centre may be within {@code range} of {@code at}. */
    void forEachWithin(Vec3 at, double range, Consumer<Agent> action) {
        forEachInBox(at.x() - range, at.z() - range, at.x() + range, at.z() + range, action);
    }

    /** How many cells a box query over this rectangle visits. */
    long cellsIn(double minX, double minZ, double maxX, double maxZ) {
        return ((long) index(maxX) - index(minX) + 1) * ((long) index(maxZ) - index(minZ) + 1);
    }

    /** Calls {@code action} for every agent whose centre may lie in the rectangle. */
    void forEachInBox(double minX, double minZ, double maxX, double maxZ, Consumer<Agent> action) {
        int x0 = index(minX);
        int x1 = index(maxX);
        int z0 = index(minZ);
        int z1 = index(maxZ);
        for (int x = x0; x <= x1; x++) {
            for (int z = z0; z <= z1; z++) {
                List<Agent> here = listAt(key(x, z), false);
                if (here != null) {
                    for (int i = 0; i < here.size(); i++) {
                        action.accept(here.get(i));
                    }
                }
            }
        }
    }

    private int index(double coordinate) {
        return (int) Math.floor(coordinate / cell);
    }

    /** The cell's coordinates packed in a long: unique per cell, never {@link #EMPTY}. */
    private static long key(int x, int z) {
        return ((long) x << 32) | (z & 0xFFFFFFFFL);
    }

    /** The list of the cell with this key; null when it has none and {@code create} is false. */
    private List<Agent> listAt(long key, boolean create) {
        int mask = keys.length - 1;
        int slot = spread(key) & mask;
        while (keys[slot] != EMPTY) {
            if (keys[slot] == key) {
                return lists[slot];
            }
            slot = (slot + 1) & mask;
        }
        if (!create) {
            return null;
        }
        if (2 * (used + 1) > keys.length) {
            grow();
            return listAt(key, true);
        }
        keys[slot] = key;
        lists[slot] = new ArrayList<>(4);
        used++;
        return lists[slot];
    }

    private static int spread(long key) {
        long h = key * 0x9E3779B97F4A7C15L;
        return (int) (h ^ (h >>> 32));
    }

    private void grow() {
        long[] oldKeys = keys;
        List<Agent>[] oldLists = lists;
        allocate(oldKeys.length * 2);
        int mask = keys.length - 1;
        for (int i = 0; i < oldKeys.length; i++) {
            if (oldKeys[i] != EMPTY) {
                int slot = spread(oldKeys[i]) & mask;
                while (keys[slot] != EMPTY) {
                    slot = (slot + 1) & mask;
                }
                keys[slot] = oldKeys[i];
                lists[slot] = oldLists[i];
                used++;
            }
        }
    }

    @SuppressWarnings("unchecked")
    private void allocate(int capacity) {
        keys = new long[capacity];
        Arrays.fill(keys, EMPTY);
        lists = new List[capacity];
        used = 0;
    }
}
