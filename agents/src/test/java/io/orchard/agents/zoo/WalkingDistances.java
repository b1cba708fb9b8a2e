package io.orchard.agents.zoo;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.World;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * How far one body has to walk, in the recorded world, to a spot from which its gripper reaches a
 * fruit: the server's own geometry ({@link World#checkPlace}) rasterised on a grid of
 * {@value #CELL}-unit cells, a cell walkable when the body can stand at its centre with a little
 * room, eight neighbours (no corner cut), and one distance field per fruit, made the first time it
 * is asked for. The world is static, so a field holds for the whole game. The fields know the whole
 * world, the castle and the river included, so a fruit a move was refused on the way to is still
 * as near as the way around the obstacle.
 */
final class WalkingDistances {

    static final double CELL = 0.5;

    /** Room kept from obstacles by the cells counted walkable, for perception's rounding. */
    private static final double ROOM = 0.05;

    /** Perception's rounding of positions, and a little more. */
    private static final double ROUNDING = 0.011;

    /** How much nearer than the exact reach a spot must be, as the agents' harvester keeps. */
    private static final double SLACK = 0.1;

    private final Bounds bounds;
    private final Body body;
    private final int nx;
    private final int nz;
    private final boolean[] walkable;
    private final Map<String, float[]> fields = new HashMap<>();

    WalkingDistances(World world, Body body) {
        this.bounds = world.bounds();
        this.body = body;
        this.nx = (int) Math.ceil(bounds.width() / CELL);
        this.nz = (int) Math.ceil(bounds.depth() / CELL);
        this.walkable = new boolean[nx * nz];
        for (int i = 0; i < walkable.length; i++) {
            walkable[i] = world.checkPlace(centre(i), body.radius() + ROOM).isFree();
        }
    }

    /**
     * Whether the body's gripper reaches the fruit's height with room for perception's rounding to
     * a hundredth: an agent that sees a fruit at 2.30 cannot tell whether a gripper reaching 2.3
     * gets it.
     */
    boolean reachesHeight(FruitState fruit) {
        double y = fruit.position().y();
        return y >= body.gripper().minHeight() + ROUNDING && y <= body.gripper().maxHeight() - ROUNDING;
    }

    /**
     * The length of the shortest walk from {@code from} to a spot within reach of the fruit;
     * infinite when the gripper does not reach its height or no walk leads there.
     */
    double to(FruitState fruit, Point2 from) {
        if (!reachesHeight(fruit)) {
            return Double.POSITIVE_INFINITY;
        }
        float[] field = fields.computeIfAbsent(fruit.id(), id -> field(fruit));
        int here = index(from);
        if (walkable[here]) {
            return field[here];
        }
        // Standing closer to a trunk than the cells allow: go on from the nearest walkable cell.
        double best = Double.POSITIVE_INFINITY;
        int ci = column(from.x());
        int ck = row(from.z());
        for (int k = Math.max(0, ck - 3); k <= Math.min(nz - 1, ck + 3); k++) {
            for (int i = Math.max(0, ci - 3); i <= Math.min(nx - 1, ci + 3); i++) {
                int cell = k * nx + i;
                if (walkable[cell]) {
                    best = Math.min(best, field[cell] + from.distance(centre(cell)));
                }
            }
        }
        return best;
    }

    /** Dijkstra from every walkable cell within reach of the fruit, outwards. */
    private float[] field(FruitState fruit) {
        float[] distance = new float[walkable.length];
        Arrays.fill(distance, Float.POSITIVE_INFINITY);
        Point2 at = fruit.position().onGround();
        double reach = body.radius() + body.gripper().reach() + fruit.kind().radius() - SLACK;
        Heap open = new Heap();
        for (int k = row(at.z() - reach); k <= row(at.z() + reach); k++) {
            for (int i = column(at.x() - reach); i <= column(at.x() + reach); i++) {
                int cell = k * nx + i;
                if (walkable[cell] && centre(cell).distance(at) <= reach) {
                    distance[cell] = 0;
                    open.push(cell, 0);
                }
            }
        }
        float diagonal = (float) (CELL * Math.sqrt(2));
        while (!open.isEmpty()) {
            float d = open.topKey();
            int cell = open.pop();
            if (d > distance[cell]) {
                continue; // a stale entry: the cell was reached by a shorter way since
            }
            int i = cell % nx;
            int k = cell / nx;
            for (int dk = -1; dk <= 1; dk++) {
                for (int di = -1; di <= 1; di++) {
                    int ni = i + di;
                    int nk = k + dk;
                    if ((di == 0 && dk == 0) || ni < 0 || nk < 0 || ni >= nx || nk >= nz) {
                        continue;
                    }
                    int neighbour = nk * nx + ni;
                    if (!walkable[neighbour]
                            || (di != 0 && dk != 0 && (!walkable[k * nx + ni] || !walkable[nk * nx + i]))) {
                        continue;
                    }
                    float through = d + (di != 0 && dk != 0 ? diagonal : (float) CELL);
                    if (through < distance[neighbour]) {
                        distance[neighbour] = through;
                        open.push(neighbour, through);
                    }
                }
            }
        }
        return distance;
    }

    private Point2 centre(int cell) {
        return new Point2(bounds.minX() + (cell % nx + 0.5) * CELL, bounds.minZ() + (cell / nx + 0.5) * CELL);
    }

    private int index(Point2 p) {
        return row(p.z()) * nx + column(p.x());
    }

    private int column(double x) {
        return Math.max(0, Math.min(nx - 1, (int) Math.floor((x - bounds.minX()) / CELL)));
    }

    private int row(double z) {
        return Math.max(0, Math.min(nz - 1, (int) Math.floor((z - bounds.minZ()) / CELL)));
    }

    /** A binary min-heap of cells keyed by distance; a cell may be in it more than once. */
    private static final class Heap {
        private int[] cells = new int[1024];
        private float[] keys = new float[1024];
        private int size;

        boolean isEmpty() {
            return size == 0;
        }

        float topKey() {
            return keys[0];
        }

        void push(int cell, float key) {
            if (size == cells.length) {
                cells = Arrays.copyOf(cells, size * 2);
                keys = Arrays.copyOf(keys, size * 2);
            }
            int i = size++;
            while (i > 0 && keys[(i - 1) >>> 1] > key) {
                int up = (i - 1) >>> 1;
                cells[i] = cells[up];
                keys[i] = keys[up];
                i = up;
            }
            cells[i] = cell;
            keys[i] = key;
        }

        int pop() {
            int top = cells[0];
            int cell = cells[--size];
            float key = keys[size];
            int i = 0;
            while (2 * i + 1 < size) {
                int child = 2 * i + 1;
                if (child + 1 < size && keys[child + 1] < keys[child]) {
                    child++;
                }
                if (keys[child] >= key) {
                    break;
                }
                cells[i] = cells[child];
                keys[i] = keys[child];
                i = child;
            }
            cells[i] = cell;
            keys[i] = key;
            return top;
        }
    }
}
