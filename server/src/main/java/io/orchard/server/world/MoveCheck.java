package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Checks;
import io.orchard.server.world.MoveResult.Obstruction;

/**
 * Decides whether an agent, a vertical cylinder of radius r, may move in a straight line from one
 * point to another: the disc swept along the segment must stay within the world, must not overlap a
 * tree's trunk, a table or the castle, and may overlap the river only where a bridge's deck covers
 * it. Merely touching is allowed.
 *
 * <p>Trees and tables are circles, tested with plain arithmetic after a grid lookup; the castle and
 * the uncovered water are prepared {@link Region}s. When several things are in the way the answer
 * names the one the agent would touch first. A move of length zero asks whether the agent may stand
 * at a point, and its reasons say "position" instead of "path".
 *
 * <p>Immutable and allocation-light: it runs for every agent on every tick.
 */
final class MoveCheck {

    private final Bounds bounds;
    private final Obstacles obstacles;
    private final Region castle;
    private final Region water;

    /**
     * @param water the river without the bridges' decks: where agents must not be
     */
    MoveCheck(Bounds bounds, Obstacles obstacles, Region castle, Region water) {
        this.bounds = bounds;
        this.obstacles = obstacles;
        this.castle = castle;
        this.water = water;
    }

    MoveResult check(double ax, double az, double bx, double bz, double radius) {
        Checks.positive(radius, "radius");
        Checks.finite(ax, "from.x");
        Checks.finite(az, "from.z");
        Checks.finite(bx, "to.x");
        Checks.finite(bz, "to.z");
        boolean standing = ax == bx && az == bz;
        Blocker first = new Blocker();
        edge(ax, az, bx, bz, radius, first);
        circles(ax, az, bx, bz, radius, first);
        if (castle.touchedBy(ax, az, bx, bz, radius)) {
            first.offer(castle.firstContact(ax, az, bx, bz, radius), Obstruction.CASTLE, -1);
        }
        if (water.touchedBy(ax, az, bx, bz, radius)) {
            first.offer(water.firstContact(ax, az, bx, bz, radius), Obstruction.RIVER, -1);
        }
        return first.obstruction == Obstruction.NONE ? MoveResult.free(standing) : first.result(standing);
    }

    /** The first fraction at which the disc's edge would cross the world's edge, if it does. */
    private void edge(double ax, double az, double bx, double bz, double radius, Blocker first) {
        double t = Math.min(
                Math.min(leave(ax, bx, bounds.minX() + radius, true), leave(ax, bx, bounds.maxX() - radius, false)),
                Math.min(leave(az, bz, bounds.minZ() + radius, true), leave(az, bz, bounds.maxZ() - radius, false)));
        if (t <= 1) {
            first.offer(t, Obstruction.EDGE, -1);
        }
    }

    /** When a coordinate going from a to b passes the limit (below it for a lower limit); above 1 if never. */
    private static double leave(double a, double b, double limit, boolean lower) {
        boolean startOut = lower ? a < limit - Plane.EPSILON : a > limit + Plane.EPSILON;
        boolean endOut = lower ? b < limit - Plane.EPSILON : b > limit + Plane.EPSILON;
        if (startOut) {
            return 0;
        }
        if (!endOut) {
            return 2;
        }
        return Math.max(0, Math.min(1, (limit - a) / (b - a)));
    }

    private void circles(double ax, double az, double bx, double bz, double radius, Blocker first) {
        double margin = radius + obstacles.maxBlockRadius;
        obstacles.grid.forEachInBox(Math.min(ax, bx) - margin, Math.min(az, bz) - margin,
                Math.max(ax, bx) + margin, Math.max(az, bz) + margin, i -> {
                    double reach = obstacles.blockRadius[i] + radius;
                    double limit = reach - Plane.EPSILON;
                    double cx = obstacles.x[i];
                    double cz = obstacles.z[i];
                    if (Plane.segmentPointDistanceSq(ax, az, bx, bz, cx, cz) < limit * limit) {
                        double t = Plane.firstContact(ax, az, bx, bz, cx, cz, reach);
                        if (Double.isNaN(t)) {
                            t = Plane.closestApproach(ax, az, bx, bz, cx, cz); // grazing, lost to rounding
                        }
                        first.offer(t, obstacles.isTree(i) ? Obstruction.TREE : Obstruction.TABLE, i);
                    }
                });
    }

    /** The earliest obstruction offered so far. */
    private final class Blocker {
        private Obstruction obstruction = Obstruction.NONE;
        private double travel = 2;
        private int item = -1;

        void offer(double at, Obstruction what, int which) {
            if (at < travel) {
                travel = at;
                obstruction = what;
                item = which;
            }
        }

        MoveResult result(boolean standing) {
            String id = item >= 0 ? obstacles.id(item) : null;
            return new MoveResult(obstruction, id, travel, reason(standing, id));
        }

        private String reason(boolean standing, String id) {
            return switch (obstruction) {
                case EDGE -> standing ? "position is outside the world" : "path leaves the world";
                case TREE -> (standing ? "position overlaps tree " : "path crosses tree ") + id;
                case TABLE -> (standing ? "position overlaps table " : "path crosses table ") + id;
                case CASTLE -> standing ? "position overlaps the castle" : "path enters the castle";
                case RIVER -> standing ? "position is in the river outside a bridge"
                        : "path enters the river outside a bridge";
                case NONE -> throw new IllegalStateException("no obstruction");
            };
        }
    }
}
