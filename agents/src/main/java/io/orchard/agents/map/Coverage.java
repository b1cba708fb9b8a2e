package io.orchard.agents.map;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sight;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Predicate;

/**
 * Which parts of the world the agent has looked at: a grid of {@value #CELL}-unit cells, each seen
 * once its centre has been in the agent's view cone well within range. Exploring means heading
 * for cells not yet seen; a cell the agent could not reach can be given up.
 *
 * <p>Not thread-safe.
 */
public final class Coverage {

    /** The side of a cell, in units. */
    public static final double CELL = 5;

    /** The share of the sight range within which a cell counts as seen. */
    public static final double RANGE_SHARE = 0.85;

    private final Bounds bounds;
    private final int nx;
    private final int nz;
    private final boolean[] seen;
    private final boolean[] givenUp;
    private int seenCount;
    private Predicate<Point2> excluded = cell -> false;

    /** An empty coverage of the world's bounds. */
    public Coverage(Bounds bounds) {
        this.bounds = bounds;
        this.nx = Math.max(1, (int) Math.ceil(bounds.width() / CELL));
        this.nz = Math.max(1, (int) Math.ceil(bounds.depth() / CELL));
        this.seen = new boolean[nx * nz];
        this.givenUp = new boolean[nx * nz];
    }

    /** Marks what an agent at {@code from} with this heading and sight sees. */
    public void look(Point2 from, double heading, Sight sight) {
        double range = sight.range() * RANGE_SHARE;
        double half = sight.fieldOfView() / 2;
        int i0 = Math.max(0, (int) Math.floor((from.x() - range - bounds.minX()) / CELL));
        int i1 = Math.min(nx - 1, (int) Math.floor((from.x() + range - bounds.minX()) / CELL));
        int k0 = Math.max(0, (int) Math.floor((from.z() - range - bounds.minZ()) / CELL));
        int k1 = Math.min(nz - 1, (int) Math.floor((from.z() + range - bounds.minZ()) / CELL));
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = k * nx + i;
                if (seen[index]) {
                    continue;
                }
                Point2 centre = centre(index);
                double distance = from.distance(centre);
                if (distance <= range && (distance < CELL
                        || Math.abs(Bearings.bearing(from, heading, centre)) <= half)) {
                    seen[index] = true;
                    seenCount++;
                }
            }
        }
    }

    /** Whether the cell holding the point has been seen. */
    public boolean seen(Point2 point) {
        int index = indexOf(point);
        return index >= 0 && seen[index];
    }

    /** The share of the world's cells seen, 0 to 1. */
    public double fractionSeen() {
        return (double) seenCount / seen.length;
    }

    /** The centres of the cells neither seen, nor given up, nor excluded. */
    public List<Point2> unseen() {
        List<Point2> cells = new ArrayList<>();
        for (int i = 0; i < seen.length; i++) {
            if (!seen[i] && !givenUp[i]) {
                Point2 centre = centre(i);
                if (!excluded.test(centre)) {
                    cells.add(centre);
                }
            }
        }
        return cells;
    }

    /**
     * Leaves out of {@link #unseen()} the cells whose centre this excludes, for as long as it does: the
     * areas the agent was told not to enter ({@link Conduct}). Unlike a cell given up, an excluded
     * cell is offered again once the rule is lifted.
     */
    public void exclude(Predicate<Point2> cells) {
        this.excluded = java.util.Objects.requireNonNull(cells, "cells");
    }

    /** Gives up the cell holding the point: it will not be offered by {@link #unseen()} again. */
    public void giveUp(Point2 point) {
        int index = indexOf(point);
        if (index >= 0) {
            givenUp[index] = true;
        }
    }

    /**
     * Forgets what was seen and given up, so that every cell is offered again: for a second look
     * at a world that was seen whole without finding what was sought.
     */
    public void lookAgain() {
        Arrays.fill(seen, false);
        Arrays.fill(givenUp, false);
        seenCount = 0;
    }

    private Point2 centre(int index) {
        double x = bounds.minX() + (index % nx + 0.5) * CELL;
        double z = bounds.minZ() + (index / nx + 0.5) * CELL;
        return new Point2(Math.min(x, bounds.maxX()), Math.min(z, bounds.maxZ()));
    }

    private int indexOf(Point2 point) {
        int i = (int) Math.floor((point.x() - bounds.minX()) / CELL);
        int k = (int) Math.floor((point.z() - bounds.minZ()) / CELL);
        if (i < 0 || k < 0 || i >= nx || k >= nz) {
            return -1;
        }
        return k * nx + i;
    }
}
