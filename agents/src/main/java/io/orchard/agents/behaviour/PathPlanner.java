package io.orchard.agents.behaviour;

import io.orchard.agents.map.Circle;
import io.orchard.agents.map.KnownObstacle;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Plans paths over the remembered map for one agent's body: A* on a grid of half-unit cells
 * (eight neighbours, octile distance), around the trunks and tables the agent has seen, over the
 * river only by a bridge's deck, around where the castle is likely to be and around what rejected
 * moves taught, and out of the areas the rules a person set keep the agent out of; then straightened by pulling the path tight wherever the straight way is clear.
 * Paths keep a little room from obstacles, because perception is rounded and the server refuses a
 * move that merely overlaps a trunk.
 *
 * <p>What the memory does not know is taken to be free: an agent plans optimistically, walks, sees
 * more and plans again. Other agents are not part of the map; pass them as temporary circles.
 *
 * <pre>{@code
 * PathPlanner planner = new PathPlanner(memory);
 * Optional<List<Point2>> path = planner.plan(memory.position(), new Point2(10, -20));
 * }</pre>
 *
 * <p>Not thread-safe; one planner per agent, on its controller's thread.
 */
public final class PathPlanner {

    /** The room kept from obstacles by straight stretches of a path. */
    public static final double MARGIN = 0.15;

    /** How near its start or its goal a path may pass too close to obstacles: an agent in a tight spot steps out. */
    static final double ESCAPE = 1.2;

    private static final double SAMPLE = 0.2;

    private final WorldMemory memory;
    private final TerrainGrid grid;
    private final GridSearch search;
    private final double radius;

    /** A planner for the agent whose memory this is (the memory knows its body radius). */
    public PathPlanner(WorldMemory memory) {
        this.memory = memory;
        this.grid = new TerrainGrid(memory);
        this.radius = memory.radius();
        this.search = new GridSearch(grid, radius);
    }

    /** A path from {@code from} to {@code to}: the points to walk through, ending at {@code to}; empty when there is none. */
    public Optional<List<Point2>> plan(Point2 from, Point2 to) {
        return plan(from, to, List.of());
    }

    /**
     * A path that also keeps clear of {@code others}: circles (other agents' bodies) that the
     * agent's body must not overlap.
     */
    public Optional<List<Point2>> plan(Point2 from, Point2 to, List<Circle> others) {
        grid.refresh();
        Bounds b = grid.bounds;
        Point2 goal = new Point2(clamp(to.x(), b.minX() + radius + 0.1, b.maxX() - radius - 0.1),
                clamp(to.z(), b.minZ() + radius + 0.1, b.maxZ() - radius - 0.1));
        if (clear(from, goal, MARGIN, others)) {
            return Optional.of(List.of(goal));
        }
        int[] cells = search.search(from, goal, standable(goal, 0.02), others);
        if (cells == null) {
            return Optional.empty();
        }
        List<Point2> raw = new ArrayList<>(cells.length + 1);
        raw.add(from);
        for (int i = 1; i < cells.length - 1; i++) {
            raw.add(new Point2(grid.cx(cells[i]), grid.cz(cells[i])));
        }
        raw.add(goal);
        return Optional.of(straighten(raw, others));
    }

    /** Whether the straight way from {@code a} to {@code b} is clear on the map, with {@link #MARGIN} to spare. */
    public boolean clear(Point2 a, Point2 b) {
        return clear(a, b, MARGIN, List.of());
    }

    /**
     * Whether the agent's body can walk straight from {@code a} to {@code b} on the map: keeping
     * {@code margin} from trunks, tables and {@code others}, inside the world, off the water and
     * the castle and what rejected moves taught.
     */
    public boolean clear(Point2 a, Point2 b, double margin, List<Circle> others) {
        grid.refresh();
        if (!inside(b, 0.05)) {
            return false;
        }
        for (KnownObstacle obstacle : memory.obstacles()) {
            double reach = obstacle.blockRadius() + obstacle.margin() + radius + margin;
            Point2 c = obstacle.centre();
            if (Math.abs(c.x() - a.x()) > reach + Math.abs(b.x() - a.x()) + 1
                    || Math.abs(c.z() - a.z()) > reach + Math.abs(b.z() - a.z()) + 1) {
                continue;
            }
            if (TerrainGrid.segmentDistance(a, b, c.x(), c.z()) < reach && a.distance(c) >= reach - 1e-9) {
                return false;
            }
            if (a.distance(c) < reach && TerrainGrid.segmentDistance(a, b, c.x(), c.z()) < a.distance(c) - 1e-6) {
                return false; // already too close: only ways that lead away are clear
            }
        }
        for (Circle other : others) {
            double reach = other.radius() + radius + margin;
            double now = Math.hypot(a.x() - other.x(), a.z() - other.z());
            double d = TerrainGrid.segmentDistance(a, b, other.x(), other.z());
            if (d < reach && (now >= reach || d < now - 1e-6)) {
                return false;
            }
        }
        double length = a.distance(b);
        int steps = (int) Math.ceil(length / SAMPLE);
        int startCell = grid.indexOf(a);
        boolean startBlocked = grid.terrain[startCell] == TerrainGrid.BLOCKED;
        boolean ruled = grid.avoided[startCell] == 0; // a rule's area may be left, not entered
        Point2 castle = memory.castle().located() ? memory.castle().centre().orElse(null) : null;
        double floor = castle == null ? 0 : Math.min(a.distance(castle), b.distance(castle)) - 0.3;
        for (int s = 1; s <= steps; s++) {
            double f = (double) s / steps;
            double x = a.x() + (b.x() - a.x()) * f;
            double z = a.z() + (b.z() - a.z()) * f;
            int cell = grid.index(grid.column(x), grid.row(z));
            if (grid.terrain[cell] == TerrainGrid.BLOCKED && !(startBlocked && f * length < ESCAPE)) {
                return false;
            }
            if (ruled && grid.avoided[cell] != 0) {
                return false;
            }
            if (castle != null && grid.extra[cell] > 0 && Math.hypot(x - castle.x(), z - castle.z()) < floor) {
                return false; // a straight stretch may skirt the castle, not cut in closer than its ends
            }
        }
        return true;
    }

    /**
     * Whether the agent's body can stand at {@code p}, keeping {@code margin} from trunks and tables,
     * outside the areas the rules keep it out of.
     */
    public boolean standable(Point2 p, double margin) {
        grid.refresh();
        if (!inside(p, 0.05) || grid.terrain[grid.indexOf(p)] == TerrainGrid.BLOCKED || grid.avoided(p)) {
            return false;
        }
        for (KnownObstacle obstacle : memory.obstacles()) {
            if (p.distance(obstacle.centre()) < obstacle.blockRadius() + obstacle.margin() + radius + margin) {
                return false;
            }
        }
        return true;
    }

    /** Whether the map rules the point out for walking: water, the castle's core, the world's edge or a learned block. */
    public boolean offLimits(Point2 p) {
        grid.refresh();
        return !inside(p, 0) || grid.terrain[grid.indexOf(p)] == TerrainGrid.BLOCKED;
    }

    /** The length of walking from {@code from} through every point of {@code path}. */
    public static double length(Point2 from, List<Point2> path) {
        double total = 0;
        Point2 at = from;
        for (Point2 p : path) {
            total += at.distance(p);
            at = p;
        }
        return total;
    }

    private boolean inside(Point2 p, double spare) {
        Bounds b = grid.bounds;
        return p.x() >= b.minX() + radius + spare && p.x() <= b.maxX() - radius - spare
                && p.z() >= b.minZ() + radius + spare && p.z() <= b.maxZ() - radius - spare;
    }

    private static double clamp(double v, double lo, double hi) {
        return Math.max(lo, Math.min(hi, v));
    }

    /** Pulls the path tight: from each corner, on to the farthest point still in straight sight. */
    private List<Point2> straighten(List<Point2> raw, List<Circle> others) {
        List<Point2> tight = new ArrayList<>();
        int anchor = 0;
        int last = raw.size() - 1;
        while (anchor < last) {
            int good = anchor + 1;
            int bad = -1;
            for (int step = 2; ; step *= 2) {
                int probe = Math.min(last, anchor + step);
                if (probe <= good) {
                    break;
                }
                if (clear(raw.get(anchor), raw.get(probe), MARGIN, others)) {
                    good = probe;
                } else {
                    bad = probe;
                    break;
                }
            }
            while (bad != -1 && bad - good > 1) {
                int mid = (good + bad) >>> 1;
                if (clear(raw.get(anchor), raw.get(mid), MARGIN, others)) {
                    good = mid;
                } else {
                    bad = mid;
                }
            }
            tight.add(raw.get(good));
            anchor = good;
        }
        return tight;
    }
}
