package io.orchard.agents.behaviour;

import io.orchard.agents.map.CastleEstimate;
import io.orchard.agents.map.Circle;
import io.orchard.agents.map.Conduct;
import io.orchard.agents.map.KnownBridge;
import io.orchard.agents.map.KnownObstacle;
import io.orchard.agents.map.LearnedBlock;
import io.orchard.agents.map.RiverMap;
import io.orchard.agents.map.Trail;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import java.util.Arrays;

/**
 * The remembered map rasterised for one agent's body: a grid of {@value #CELL}-unit cells, each
 * FREE, NEAR (close to something: walkable at a cost), TIGHT (within a hair of an obstacle:
 * walkable only near the start and the end of a path) or BLOCKED (the body would overlap a trunk,
 * a table, the water away from a bridge, the castle's likely core, or something a rejected move
 * ran into). Where the agent has stood ({@link Trail}) is never blocked by the layers that are
 * guesses (the water, the castle, what refused moves taught): it stood there, so a path can lead
 * it out the way it came. Rebuilt from the memory when its terrain changes; the river layer, the
 * costliest, only when the river model changed. A separate layer marks the cells the rules a
 * person set keep the agent out of ({@link io.orchard.agents.map.Conduct}), widened by a cell so
 * that a path planned on the grid keeps out of them point by point.
 */
final class TerrainGrid {

    static final double CELL = 0.5;
    static final byte FREE = 0;
    static final byte NEAR = 1;
    static final byte TIGHT = 2;
    static final byte BLOCKED = 3;

    /** Extra room kept from obstacles: cells this close beyond the body's reach are TIGHT. */
    static final double TIGHT_MARGIN = 0.25;
    static final double NEAR_MARGIN = 0.7;
    static final double WATER_MARGIN = 0.4;
    static final double CASTLE_CORE = CastleEstimate.CORE_RADIUS + 2;
    static final double CANDIDATE_CORE = 3;

    private final WorldMemory memory;
    private final double radius;
    final Bounds bounds;
    final int nx;
    final int nz;
    /** Everything: what A* reads. */
    final byte[] cells;
    /** Extra cost per unit walked through a cell (around the castle). */
    final float[] extra;
    /** The layers that are not circles (water, castle, learned blocks, edges): what straight checks sample. */
    final byte[] terrain;
    private final byte[] wet;
    private final byte[] edge;
    /** The cells the rules keep the agent out of: nonzero where it may not walk, unless it stands in one. */
    final byte[] avoided;
    private long builtVersion = -1;
    private long wetVersion = -1;

    TerrainGrid(WorldMemory memory) {
        this.memory = memory;
        this.radius = memory.radius();
        this.bounds = memory.bounds();
        this.nx = (int) Math.ceil(bounds.width() / CELL);
        this.nz = (int) Math.ceil(bounds.depth() / CELL);
        this.cells = new byte[nx * nz];
        this.extra = new float[nx * nz];
        this.terrain = new byte[nx * nz];
        this.wet = new byte[nx * nz];
        this.edge = new byte[nx * nz];
        this.avoided = new byte[nx * nz];
        edges();
    }

    /** Brings the grid up to date with the memory. */
    void refresh() {
        long version = memory.terrainVersion();
        if (version == builtVersion) {
            return;
        }
        builtVersion = version;
        RiverMap river = memory.river();
        if (river.version() != wetVersion) {
            wetVersion = river.version();
            rasteriseWater(river);
        }
        for (int i = 0; i < terrain.length; i++) {
            terrain[i] = (byte) Math.max(wet[i], edge[i]);
        }
        Arrays.fill(extra, 0f);
        castle();
        for (LearnedBlock block : memory.learned()) {
            learned(block);
        }
        memory.trail().forEach(this::trodden);
        System.arraycopy(terrain, 0, cells, 0, terrain.length);
        for (KnownObstacle obstacle : memory.obstacles()) {
            circle(obstacle.centre(), obstacle.blockRadius() + obstacle.margin());
        }
        rules();
    }

    /** Whether the rules keep the agent out of the cell holding this point. */
    boolean avoided(Point2 p) {
        return avoided[indexOf(p)] != 0;
    }

    /**
     * The cells the rules keep the agent out of: those whose centre, or a neighbour's, is in a rule's
     * area, looked at every other cell and every cell near an edge of an area.
     */
    private void rules() {
        Arrays.fill(avoided, (byte) 0);
        Conduct conduct = memory.conduct();
        if (!conduct.restrictsPlaces()) {
            return;
        }
        byte[] in = new byte[nx * nz];
        for (int k = 0; k < nz; k += 2) {
            for (int i = 0; i < nx; i += 2) {
                int index = index(i, k);
                in[index] = (byte) (conduct.forbids(new Point2(cx(index), cz(index))) ? 1 : 0);
            }
        }
        for (int k = 0; k < nz; k++) {
            for (int i = 0; i < nx; i++) {
                if (i % 2 == 0 && k % 2 == 0) {
                    continue;
                }
                int i0 = i - i % 2;
                int k0 = k - k % 2;
                int i1 = Math.min(i0 + 2, nx - 1 - (nx - 1) % 2);
                int k1 = Math.min(k0 + 2, nz - 1 - (nz - 1) % 2);
                byte a = in[index(i0, k0)];
                boolean same = a == in[index(i1, k0)] && a == in[index(i0, k1)] && a == in[index(i1, k1)];
                int index = index(i, k);
                in[index] = same ? a : (byte) (conduct.forbids(new Point2(cx(index), cz(index))) ? 1 : 0);
            }
        }
        for (int k = 0; k < nz; k++) {
            for (int i = 0; i < nx; i++) {
                if (in[index(i, k)] == 0) {
                    continue;
                }
                for (int dk = -1; dk <= 1; dk++) {
                    for (int di = -1; di <= 1; di++) {
                        int ii = i + di;
                        int kk = k + dk;
                        if (ii >= 0 && kk >= 0 && ii < nx && kk < nz) {
                            avoided[index(ii, kk)] = 1;
                        }
                    }
                }
            }
        }
    }

    int index(int i, int k) {
        return k * nx + i;
    }

    int column(double x) {
        return Math.max(0, Math.min(nx - 1, (int) Math.floor((x - bounds.minX()) / CELL)));
    }

    int row(double z) {
        return Math.max(0, Math.min(nz - 1, (int) Math.floor((z - bounds.minZ()) / CELL)));
    }

    int indexOf(Point2 p) {
        return index(column(p.x()), row(p.z()));
    }

    double cx(int index) {
        return bounds.minX() + (index % nx + 0.5) * CELL;
    }

    double cz(int index) {
        return bounds.minZ() + (index / nx + 0.5) * CELL;
    }

    /** Ground the agent stood on: walkable at a cost, whatever the guesses say, unless beyond the world's edge. */
    private void trodden(Point2 p) {
        int index = indexOf(p);
        if (terrain[index] == BLOCKED && edge[index] != BLOCKED) {
            terrain[index] = NEAR;
        }
    }

    /** Marks the cells around a blocking circle: BLOCKED where the body would overlap it, TIGHT and NEAR around. */
    private void circle(Point2 centre, double block) {
        double outer = block + radius + NEAR_MARGIN;
        int i0 = column(centre.x() - outer);
        int i1 = column(centre.x() + outer);
        int k0 = row(centre.z() - outer);
        int k1 = row(centre.z() + outer);
        double hard = block + radius + 0.02;
        double tight = block + radius + TIGHT_MARGIN;
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = index(i, k);
                double d = Math.hypot(cx(index) - centre.x(), cz(index) - centre.z());
                byte state = d < hard ? BLOCKED : d < tight ? TIGHT : d < outer ? NEAR : FREE;
                if (state > cells[index]) {
                    cells[index] = state;
                }
            }
        }
    }

    private void edges() {
        for (int k = 0; k < nz; k++) {
            for (int i = 0; i < nx; i++) {
                int index = index(i, k);
                double x = cx(index);
                double z = cz(index);
                double fromEdge = Math.min(Math.min(x - bounds.minX(), bounds.maxX() - x),
                        Math.min(z - bounds.minZ(), bounds.maxZ() - z));
                edge[index] = fromEdge < radius + 0.1 ? BLOCKED : fromEdge < radius + 0.5 ? NEAR : FREE;
            }
        }
    }

    /**
     * Once the castle is near (a move ran into it) or located, every candidate centre left
     * blocks a disc of {@value #CANDIDATE_CORE} around it: the castle's core, less the estimate's
     * slack. A located castle also makes walking within its greatest reach costly.
     */
    private void castle() {
        CastleEstimate castle = memory.castle();
        if (castle.bounded() || castle.located()) {
            double reach = CANDIDATE_CORE + radius;
            castle.forEachCandidate((x, z) -> disc(x, z, reach));
        }
        if (!castle.located()) {
            return;
        }
        Point2 centre = castle.centre().orElseThrow();
        double outer = CastleEstimate.MAX_RADIUS + radius + 1;
        int i0 = column(centre.x() - outer);
        int i1 = column(centre.x() + outer);
        int k0 = row(centre.z() - outer);
        int k1 = row(centre.z() + outer);
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = index(i, k);
                double d = Math.hypot(cx(index) - centre.x(), cz(index) - centre.z());
                if (d < CASTLE_CORE + radius) {
                    terrain[index] = BLOCKED;
                } else if (d < outer) {
                    extra[index] = 3f;
                }
            }
        }
        for (CastleEstimate.Contact contact : castle.contacts()) {
            reach(centre, contact);
        }
    }

    /**
     * A refused move shows how far the castle reaches in that direction from its centre; the
     * castle is symmetric about its centre (a keep with a tower on each corner), so it reaches as
     * far in the opposite direction. Blocks both wedges out to that distance.
     */
    private void reach(Point2 centre, CastleEstimate.Contact contact) {
        double d = segmentDistance(contact.from(), contact.to(), centre.x(), centre.z());
        Point2 nearest = closestPoint(contact.from(), contact.to(), centre);
        double extent = d + contact.radius() + radius + 0.3;
        double towards = Math.atan2(nearest.z() - centre.z(), nearest.x() - centre.x());
        double halfWidth = Math.max(Math.toRadians(20), Math.asin(Math.min(1, 3 / Math.max(3, d))));
        int i0 = column(centre.x() - extent);
        int i1 = column(centre.x() + extent);
        int k0 = row(centre.z() - extent);
        int k1 = row(centre.z() + extent);
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = index(i, k);
                double dx = cx(index) - centre.x();
                double dz = cz(index) - centre.z();
                if (Math.hypot(dx, dz) >= extent) {
                    continue;
                }
                double off = Math.abs(Math.IEEEremainder(Math.atan2(dz, dx) - towards, Math.PI));
                if (off < halfWidth) {
                    terrain[index] = BLOCKED;
                }
            }
        }
    }

    private static Point2 closestPoint(Point2 a, Point2 b, Point2 p) {
        double dx = b.x() - a.x();
        double dz = b.z() - a.z();
        double lengthSq = dx * dx + dz * dz;
        double t = lengthSq == 0 ? 0 : Math.max(0, Math.min(1, ((p.x() - a.x()) * dx + (p.z() - a.z()) * dz) / lengthSq));
        return new Point2(a.x() + t * dx, a.z() + t * dz);
    }

    private void disc(double x, double z, double reach) {
        int i0 = column(x - reach);
        int i1 = column(x + reach);
        int k0 = row(z - reach);
        int k1 = row(z + reach);
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = index(i, k);
                if (Math.hypot(cx(index) - x, cz(index) - z) < reach) {
                    terrain[index] = BLOCKED;
                }
            }
        }
    }

    private void learned(LearnedBlock block) {
        Point2 a = block.from();
        Point2 b = block.to();
        double reach = block.radius() + 0.1;
        double spare = Math.min(radius + 0.4, 0.4 * a.distance(b)); // the agent stood at the start: keep it free
        int i0 = column(Math.min(a.x(), b.x()) - reach);
        int i1 = column(Math.max(a.x(), b.x()) + reach);
        int k0 = row(Math.min(a.z(), b.z()) - reach);
        int k1 = row(Math.max(a.z(), b.z()) + reach);
        Circle start = Circle.around(a, spare);
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = index(i, k);
                double x = cx(index);
                double z = cz(index);
                if (!start.contains(x, z) && segmentDistance(a, b, x, z) < reach) {
                    terrain[index] = BLOCKED;
                }
            }
        }
    }

    private void rasteriseWater(RiverMap river) {
        Arrays.fill(wet, FREE);
        if (!river.seen()) {
            return;
        }
        double hard = radius + WATER_MARGIN;
        double near = hard + 0.5;
        // A coarse pass first: only blocks of cells near the water are looked at cell by cell.
        int block = 4;
        double reach = block * CELL;
        for (int bk = 0; bk < nz; bk += block) {
            for (int bi = 0; bi < nx; bi += block) {
                double x = bounds.minX() + (bi + block / 2.0) * CELL;
                double z = bounds.minZ() + (bk + block / 2.0) * CELL;
                if (!river.water(x, z, near + reach)) {
                    continue;
                }
                for (int k = bk; k < Math.min(nz, bk + block); k++) {
                    for (int i = bi; i < Math.min(nx, bi + block); i++) {
                        int index = index(i, k);
                        if (river.water(cx(index), cz(index), hard)) {
                            wet[index] = BLOCKED;
                        } else if (river.water(cx(index), cz(index), near)) {
                            wet[index] = NEAR;
                        }
                    }
                }
            }
        }
        for (KnownBridge bridge : memory.bridges()) {
            deck(bridge);
        }
    }

    /** The deck covers the water: free along its middle, away from its open sides. */
    private void deck(KnownBridge bridge) {
        double outer = bridge.length() + bridge.width() + 4;
        Point2 middle = bridge.middle();
        int i0 = column(middle.x() - outer / 2);
        int i1 = column(middle.x() + outer / 2);
        int k0 = row(middle.z() - outer / 2);
        int k1 = row(middle.z() + outer / 2);
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = index(i, k);
                Point2 p = new Point2(cx(index), cz(index));
                if (bridge.covers(p, radius + 0.15, 1.5)) {
                    wet[index] = FREE;
                }
            }
        }
    }

    static double segmentDistance(Point2 a, Point2 b, double px, double pz) {
        double dx = b.x() - a.x();
        double dz = b.z() - a.z();
        double lengthSq = dx * dx + dz * dz;
        double t = lengthSq == 0 ? 0 : Math.max(0, Math.min(1, ((px - a.x()) * dx + (pz - a.z()) * dz) / lengthSq));
        return Math.hypot(a.x() + t * dx - px, a.z() + t * dz - pz);
    }
}
