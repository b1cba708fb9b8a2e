package io.orchard.agents.behaviour;

import io.orchard.agents.map.Circle;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.Arrays;

/**
 * How far the agent has to walk, on its map, to every part of the world: one Dijkstra from where
 * it stands over cells of {@value #CELL} units, around what the planner's grid holds impassable
 * (the water away from a bridge, the castle's likely core, the world's edge, what refused moves
 * taught), a walk near a castle located counting more, as the planner's does, and a walk through an
 * area a rule keeps the agent out of much more (the way out of one, for an agent that stands in
 * it). Trees and tables are left out: small beside the distances it is asked about, which are for
 * choosing where to go, not for walking there. A cell is open when any part of it is, so that a
 * bridge's deck stays a way across however it lies on the cells.
 *
 * <p>Made again only when the agent stands in another cell or that layer of the map changed.
 * Not thread-safe.
 */
final class WalkingField {

    /** The side of a cell, in units. */
    static final double CELL = 2;

    private static final int RATIO = (int) Math.round(CELL / TerrainGrid.CELL);
    private static final double DIAGONAL = Math.sqrt(2) * CELL;

    private final TerrainGrid grid;
    private final int nx;
    private final int nz;
    private final boolean[] open;
    /** For each open cell, the fine cell of the planner's grid to stand in: a free one if there is. */
    private final int[] stand;
    /** For each open cell, what a unit walked through it costs: more around a castle located. */
    private final float[] weight;
    private final float[] distance;
    private final boolean[] done;
    private final CellHeap heap;
    private long builtVersion = -1;
    private int origin = -1;

    WalkingField(TerrainGrid grid) {
        this.grid = grid;
        this.nx = (grid.nx + RATIO - 1) / RATIO;
        this.nz = (grid.nz + RATIO - 1) / RATIO;
        this.open = new boolean[nx * nz];
        this.stand = new int[nx * nz];
        this.weight = new float[nx * nz];
        this.distance = new float[nx * nz];
        this.done = new boolean[nx * nz];
        this.heap = new CellHeap(nx * nz);
    }

    /** The field from {@code here}, made again when needed. */
    WalkingField from(Point2 here) {
        grid.refresh();
        int start = index(here);
        if (start == origin && grid.edition == builtVersion) {
            return this;
        }
        if (grid.edition != builtVersion) {
            builtVersion = grid.edition;
            rasterise();
        }
        origin = start;
        spread(start);
        return this;
    }

    /** The walk to the cell holding {@code p}; infinite when no way leads there. */
    double to(Point2 p) {
        return distance[index(p)];
    }

    /**
     * The nearest point, by walking, from which {@code target} lies within {@code range} in a
     * straight line not through {@code hiding} (when given), and the walk to it; null when there is
     * none.
     */
    Viewpoint nearestWithin(Point2 target, double range, @Nullable Circle hiding) {
        int i0 = column(target.x() - range);
        int i1 = column(target.x() + range);
        int k0 = row(target.z() - range);
        int k1 = row(target.z() + range);
        int best = -1;
        float shortest = Float.POSITIVE_INFINITY;
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int cell = k * nx + i;
                if (distance[cell] < shortest && Math.hypot(grid.cx(stand[cell]) - target.x(),
                        grid.cz(stand[cell]) - target.z()) <= range && (hiding == null
                        || hiding.distanceToSegment(new Point2(grid.cx(stand[cell]), grid.cz(stand[cell])), target)
                        > hiding.radius())) {
                    shortest = distance[cell];
                    best = cell;
                }
            }
        }
        return best < 0 ? null : new Viewpoint(new Point2(grid.cx(stand[best]), grid.cz(stand[best])), shortest);
    }

    /**
     * A point to walk to and the length of the walk.
     *
     * @param at   where
     * @param walk how far
     */
    record Viewpoint(Point2 at, double walk) {}

    private void rasterise() {
        Arrays.fill(open, false);
        for (int k = 0; k < grid.nz; k++) {
            for (int i = 0; i < grid.nx; i++) {
                int fine = grid.index(i, k);
                int cell = (k / RATIO) * nx + i / RATIO;
                if (grid.terrain[fine] == TerrainGrid.BLOCKED) {
                    continue;
                }
                float cost = cost(fine);
                if (!open[cell] || cost < cost(stand[cell])
                        || (cost == cost(stand[cell]) && grid.cells[fine] < grid.cells[stand[cell]])) {
                    open[cell] = true;
                    stand[cell] = fine;
                    weight[cell] = 1 + cost;
                }
            }
        }
    }

    /** What a unit walked through a fine cell costs beyond the unit: the castle's surroundings, a rule's area. */
    private float cost(int fine) {
        return grid.extra[fine] + (grid.avoided[fine] != 0 ? (float) GridSearch.RULE_PENALTY : 0f);
    }

    private void spread(int start) {
        Arrays.fill(distance, Float.POSITIVE_INFINITY);
        Arrays.fill(done, false);
        heap.clear();
        distance[start] = 0;
        heap.push(start, 0);
        while (!heap.isEmpty()) {
            int cell = heap.pop();
            if (done[cell]) {
                continue;
            }
            done[cell] = true;
            int ci = cell % nx;
            int ck = cell / nx;
            for (int dk = -1; dk <= 1; dk++) {
                for (int di = -1; di <= 1; di++) {
                    int i = ci + di;
                    int k = ck + dk;
                    if ((di == 0 && dk == 0) || i < 0 || k < 0 || i >= nx || k >= nz) {
                        continue;
                    }
                    int next = k * nx + i;
                    if (!open[next] || done[next]) {
                        continue;
                    }
                    float through = distance[cell] + (float) (di != 0 && dk != 0 ? DIAGONAL : CELL) * weight[next];
                    if (through < distance[next]) {
                        distance[next] = through;
                        heap.push(next, through);
                    }
                }
            }
        }
    }

    private int index(Point2 p) {
        return row(p.z()) * nx + column(p.x());
    }

    private int column(double x) {
        return Math.max(0, Math.min(nx - 1, (int) Math.floor((x - grid.bounds.minX()) / CELL)));
    }

    private int row(double z) {
        return Math.max(0, Math.min(nz - 1, (int) Math.floor((z - grid.bounds.minZ()) / CELL)));
    }
}
