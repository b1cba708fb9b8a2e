package io.orchard.agents.behaviour;

import io.orchard.agents.map.Circle;
import io.orchard.protocol.value.Point2;
import java.util.Arrays;
import java.util.List;

/**
 * A* over one body's {@link TerrainGrid}: eight neighbours, octile distance, no cutting corners.
 * NEAR cells cost more than FREE ones, TIGHT cells may be walked only close to the start or the
 * goal, and BLOCKED ones never, so that an agent standing in a tight spot can still step out of
 * it. The cells the rules keep the agent out of are never walked either, unless the agent stands
 * in one: then they cost much, so that the way leads out of the area by the shortest way. The
 * arrays are kept from one search to the next and told apart by a generation number, so a search
 * allocates little.
 *
 * <p>Not thread-safe; one per {@link PathPlanner}.
 */
final class GridSearch {

    private static final double SQRT2 = Math.sqrt(2);
    private static final int MAX_EXPANSIONS = 400_000;
    /** The extra cost of a cell a rule keeps the agent out of, for an agent that stands in one and must get out. */
    private static final double RULE_PENALTY = 20;

    private final TerrainGrid grid;
    private final double radius;
    private final float[] cost;
    private final int[] parent;
    private final int[] stamp;
    private final int[] closed;
    private final Heap open;
    private int generation;
    private boolean escaping;

    GridSearch(TerrainGrid grid, double radius) {
        this.grid = grid;
        this.radius = radius;
        int size = grid.nx * grid.nz;
        this.cost = new float[size];
        this.parent = new int[size];
        this.stamp = new int[size];
        this.closed = new int[size];
        this.open = new Heap(size);
    }

    /**
     * The cells of a shortest way from {@code from} to {@code to}, both included; null when there
     * is none, or none was found within {@value #MAX_EXPANSIONS} expansions.
     *
     * @param goalStandable whether the body can stand at {@code to}: then the cells right around it
     *                      may be walked at a cost, as the grid is too coarse to tell
     * @param others        circles (other agents' bodies) whose cells may not be walked
     */
    int[] search(Point2 from, Point2 to, boolean goalStandable, List<Circle> others) {
        int start = grid.indexOf(from);
        int goal = grid.indexOf(to);
        if (++generation == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            Arrays.fill(closed, 0);
            generation = 1;
        }
        byte[] othersMask = others.isEmpty() ? null : othersMask(others, from);
        escaping = grid.avoided[start] != 0;
        if (goal != start && passable(goal, from, to, goalStandable, othersMask) < 0) {
            return null;
        }
        open.clear();
        cost[start] = 0;
        parent[start] = -1;
        stamp[start] = generation;
        open.push(start, heuristic(start, goal));
        int expansions = 0;
        int nx = grid.nx;
        while (!open.isEmpty()) {
            int current = open.pop();
            if (closed[current] == generation) {
                continue;
            }
            closed[current] = generation;
            if (current == goal) {
                return trace(goal);
            }
            if (++expansions > MAX_EXPANSIONS) {
                return null;
            }
            int ci = current % nx;
            int ck = current / nx;
            for (int dk = -1; dk <= 1; dk++) {
                for (int di = -1; di <= 1; di++) {
                    if (di == 0 && dk == 0) {
                        continue;
                    }
                    int i = ci + di;
                    int k = ck + dk;
                    if (i < 0 || k < 0 || i >= nx || k >= grid.nz) {
                        continue;
                    }
                    int next = grid.index(i, k);
                    double step = (di != 0 && dk != 0 ? SQRT2 : 1) * TerrainGrid.CELL;
                    double penalty = passable(next, from, to, goalStandable, othersMask);
                    if (penalty < 0) {
                        continue;
                    }
                    if (di != 0 && dk != 0 && (passable(grid.index(ci + di, ck), from, to, goalStandable, othersMask) < 0
                            || passable(grid.index(ci, ck + dk), from, to, goalStandable, othersMask) < 0)) {
                        continue; // no corner cutting
                    }
                    float g = (float) (cost[current] + step * (1 + penalty + grid.extra[next]));
                    if (closed[next] != generation && (stamp[next] != generation || g < cost[next])) {
                        stamp[next] = generation;
                        cost[next] = g;
                        parent[next] = current;
                        open.push(next, g + heuristic(next, goal));
                    }
                }
            }
        }
        return null;
    }

    /** The extra cost of walking through a cell, or -1 when it may not be walked. */
    private double passable(int cell, Point2 from, Point2 to, boolean goalStandable, byte[] othersMask) {
        if (othersMask != null && othersMask[cell] != 0) {
            return -1;
        }
        double rule = 0;
        if (grid.avoided[cell] != 0) {
            if (!escaping) {
                return -1; // a rule keeps the agent out
            }
            rule = RULE_PENALTY;
        }
        double penalty = terrain(cell, from, to, goalStandable);
        return penalty < 0 ? penalty : penalty + rule;
    }

    /** The extra cost of walking through a cell as the map has it, or -1 when it may not be walked. */
    private double terrain(int cell, Point2 from, Point2 to, boolean goalStandable) {
        byte state = grid.cells[cell];
        if (state == TerrainGrid.FREE) {
            return 0;
        }
        if (state == TerrainGrid.NEAR) {
            return 0.6;
        }
        double x = grid.cx(cell);
        double z = grid.cz(cell);
        boolean nearStart = Math.hypot(x - from.x(), z - from.z()) < PathPlanner.ESCAPE;
        boolean nearGoal = Math.hypot(x - to.x(), z - to.z()) < PathPlanner.ESCAPE;
        if (state == TerrainGrid.TIGHT) {
            return nearStart || nearGoal ? 3 : -1;
        }
        if (grid.terrain[cell] == TerrainGrid.BLOCKED) {
            return -1; // water, the castle, the edge or a learned block: never, not even to get going
        }
        if (nearStart && Math.hypot(x - from.x(), z - from.z()) < 0.8) {
            return 6; // next to a trunk where the grid is too coarse to tell: let the agent step out
        }
        if (goalStandable && Math.hypot(x - to.x(), z - to.z()) < 0.6) {
            return 6;
        }
        return -1;
    }

    private byte[] othersMask(List<Circle> others, Point2 from) {
        byte[] mask = new byte[grid.nx * grid.nz];
        for (Circle other : others) {
            double reach = other.radius() + radius + PathPlanner.MARGIN;
            if (Math.hypot(from.x() - other.x(), from.z() - other.z()) < reach) {
                reach = Math.hypot(from.x() - other.x(), from.z() - other.z()) - 0.05;
            }
            int i0 = grid.column(other.x() - reach);
            int i1 = grid.column(other.x() + reach);
            int k0 = grid.row(other.z() - reach);
            int k1 = grid.row(other.z() + reach);
            for (int k = k0; k <= k1; k++) {
                for (int i = i0; i <= i1; i++) {
                    int index = grid.index(i, k);
                    if (Math.hypot(grid.cx(index) - other.x(), grid.cz(index) - other.z()) < reach) {
                        mask[index] = 1;
                    }
                }
            }
        }
        return mask;
    }

    private double heuristic(int cell, int goal) {
        int dx = Math.abs(cell % grid.nx - goal % grid.nx);
        int dz = Math.abs(cell / grid.nx - goal / grid.nx);
        return (Math.max(dx, dz) + (SQRT2 - 1) * Math.min(dx, dz)) * TerrainGrid.CELL;
    }

    private int[] trace(int goal) {
        int count = 0;
        for (int c = goal; c != -1; c = parent[c]) {
            count++;
        }
        int[] path = new int[count];
        for (int c = goal, i = count - 1; c != -1; c = parent[c], i--) {
            path[i] = c;
        }
        return path;
    }

    /** A binary min-heap of cells keyed by float. */
    private static final class Heap {
        private int[] items;
        private float[] keys;
        private int size;

        Heap(int capacity) {
            items = new int[Math.max(16, capacity / 8)];
            keys = new float[items.length];
        }

        void clear() {
            size = 0;
        }

        boolean isEmpty() {
            return size == 0;
        }

        void push(int item, double key) {
            if (size == items.length) {
                items = Arrays.copyOf(items, size * 2);
                keys = Arrays.copyOf(keys, size * 2);
            }
            int i = size++;
            while (i > 0) {
                int up = (i - 1) >>> 1;
                if (keys[up] <= key) {
                    break;
                }
                items[i] = items[up];
                keys[i] = keys[up];
                i = up;
            }
            items[i] = item;
            keys[i] = (float) key;
        }

        int pop() {
            int top = items[0];
            int item = items[--size];
            float key = keys[size];
            int i = 0;
            while (true) {
                int child = 2 * i + 1;
                if (child >= size) {
                    break;
                }
                if (child + 1 < size && keys[child + 1] < keys[child]) {
                    child++;
                }
                if (keys[child] >= key) {
                    break;
                }
                items[i] = items[child];
                keys[i] = keys[child];
                i = child;
            }
            items[i] = item;
            keys[i] = key;
            return top;
        }
    }
}
