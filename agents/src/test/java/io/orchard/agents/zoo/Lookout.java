package io.orchard.agents.zoo;

import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sight;
import io.orchard.server.world.World;

/**
 * What an agent has looked at in the recorded world: cells of {@value #CELL} units, each looked at
 * once its centre was well within the agent's sight ({@value #RANGE_SHARE} of the range, in the
 * field of view) and not hidden by the castle, as the server's perception has it. An agent that
 * looks at a cell for the first time is exploring.
 */
final class Lookout {

    static final double CELL = 5;

    /** The share of the sight range within which a cell's centre must be for all of the cell to have been in sight. */
    static final double RANGE_SHARE = 0.85;

    private final World world;
    private final Sight sight;
    private final Bounds bounds;
    private final int nx;
    private final int nz;
    private final boolean[] seen;

    Lookout(World world, Sight sight) {
        this.world = world;
        this.sight = sight;
        this.bounds = world.bounds();
        this.nx = (int) Math.ceil(bounds.width() / CELL);
        this.nz = (int) Math.ceil(bounds.depth() / CELL);
        this.seen = new boolean[nx * nz];
    }

    /** Looks from {@code at} facing {@code heading}; true when a cell not looked at before came into sight. */
    boolean look(Point2 at, double heading) {
        double range = sight.range() * RANGE_SHARE;
        boolean fresh = false;
        int i0 = Math.max(0, (int) Math.floor((at.x() - range - bounds.minX()) / CELL));
        int i1 = Math.min(nx - 1, (int) Math.floor((at.x() + range - bounds.minX()) / CELL));
        int k0 = Math.max(0, (int) Math.floor((at.z() - range - bounds.minZ()) / CELL));
        int k1 = Math.min(nz - 1, (int) Math.floor((at.z() + range - bounds.minZ()) / CELL));
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int cell = k * nx + i;
                if (seen[cell]) {
                    continue;
                }
                Point2 centre = new Point2(bounds.minX() + (i + 0.5) * CELL, bounds.minZ() + (k + 0.5) * CELL);
                if (at.distance(centre) <= range
                        && Math.abs(Bearings.bearing(at, heading, centre)) <= sight.fieldOfView() / 2
                        && world.lineOfSight(at, centre)) {
                    seen[cell] = true;
                    fresh = true;
                }
            }
        }
        return fresh;
    }
}
