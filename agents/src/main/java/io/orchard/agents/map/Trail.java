package io.orchard.agents.map;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import java.util.Arrays;
import java.util.function.Consumer;

/**
 * Where the agent has stood: cells of {@value #CELL} units that its centre has been in, joined
 * along its way from one perception to the next. The server let the agent stand there, so that
 * ground is walkable for its body whatever the castle's estimate or a refused move suggest; a
 * planner that keeps it open can always lead the agent back the way it came, and never boxes it in
 * where it stands.
 *
 * <p>Not thread-safe.
 */
public final class Trail {

    /** The side of a cell, in units: the planner's cell. */
    public static final double CELL = 0.5;

    /** Two places farther apart than this are not joined: the agent did not walk between them. */
    private static final double LONGEST_STEP = 2;

    private final Bounds bounds;
    private final int nx;
    private final int nz;
    private final boolean[] stood;
    private int[] order = new int[256];
    private int count;
    private Point2 last;

    /** An empty trail over the world's bounds. */
    public Trail(Bounds bounds) {
        this.bounds = bounds;
        this.nx = Math.max(1, (int) Math.ceil(bounds.width() / CELL));
        this.nz = Math.max(1, (int) Math.ceil(bounds.depth() / CELL));
        this.stood = new boolean[nx * nz];
    }

    /** The agent stands at {@code where}: marks it, and the way from where it stood before. */
    public void stood(Point2 where) {
        if (last != null && last.distance(where) <= LONGEST_STEP) {
            int steps = (int) Math.ceil(last.distance(where) / (CELL / 2));
            for (int s = 1; s < steps; s++) {
                double f = (double) s / steps;
                mark(last.x() + (where.x() - last.x()) * f, last.z() + (where.z() - last.z()) * f);
            }
        }
        mark(where.x(), where.z());
        last = where;
    }

    /** Whether the agent's centre has been in the cell holding the point. */
    public boolean stoodAt(Point2 point) {
        int index = indexOf(point.x(), point.z());
        return index >= 0 && stood[index];
    }

    /** Calls {@code action} with the centre of every cell the agent has stood in, in the order it first did. */
    public void forEach(Consumer<Point2> action) {
        for (int i = 0; i < count; i++) {
            int index = order[i];
            action.accept(new Point2(bounds.minX() + (index % nx + 0.5) * CELL, bounds.minZ() + (index / nx + 0.5) * CELL));
        }
    }

    /** How many cells the agent has stood in. */
    public int size() {
        return count;
    }

    private void mark(double x, double z) {
        int index = indexOf(x, z);
        if (index < 0 || stood[index]) {
            return;
        }
        stood[index] = true;
        if (count == order.length) {
            order = Arrays.copyOf(order, count * 2);
        }
        order[count++] = index;
    }

    private int indexOf(double x, double z) {
        int i = (int) Math.floor((x - bounds.minX()) / CELL);
        int k = (int) Math.floor((z - bounds.minZ()) / CELL);
        if (i < 0 || k < 0 || i >= nx || k >= nz) {
            return -1;
        }
        return k * nx + i;
    }
}
