package io.orchard.agents;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.World;
import java.util.List;

/** Places in a world, as tests need them: a free one near a point, and how far one is from the water. */
public final class Places {

    private Places() {
    }

    /** A free place for an agent, as near {@code wanted} as there is one, out of the river. */
    public static Point2 freeNear(World world, Point2 wanted) {
        for (int ring = 0; ring < 20; ring++) {
            for (int k = 0; k < Math.max(1, ring * 8); k++) {
                double angle = k * 2 * Math.PI / Math.max(1, ring * 8);
                Point2 p = new Point2(wanted.x() + ring * Math.cos(angle), wanted.z() + ring * Math.sin(angle));
                if (world.checkPlace(p, 1.2).isFree() && !world.river().contains(p)) {
                    return p;
                }
            }
        }
        throw new IllegalStateException("no free place near " + wanted);
    }

    /** How far a point is from the water's shore (not counting where the river leaves the world); 0 in it. */
    public static double toWater(World world, Point2 p) {
        if (world.river().contains(p)) {
            return 0;
        }
        List<Point2> outline = world.river().outline();
        Bounds bounds = world.bounds();
        double nearest = Double.MAX_VALUE;
        for (int i = 0; i < outline.size(); i++) {
            Point2 a = outline.get(i);
            Point2 b = outline.get((i + 1) % outline.size());
            if (!(onEdge(a, bounds) && onEdge(b, bounds))) {
                nearest = Math.min(nearest, segmentDistance(p, a, b));
            }
        }
        return nearest;
    }

    private static boolean onEdge(Point2 p, Bounds bounds) {
        return Math.abs(p.x() - bounds.minX()) < 1e-6 || Math.abs(p.x() - bounds.maxX()) < 1e-6
                || Math.abs(p.z() - bounds.minZ()) < 1e-6 || Math.abs(p.z() - bounds.maxZ()) < 1e-6;
    }

    private static double segmentDistance(Point2 p, Point2 a, Point2 b) {
        double dx = b.x() - a.x();
        double dz = b.z() - a.z();
        double lengthSq = dx * dx + dz * dz;
        double t = lengthSq == 0 ? 0 : Math.max(0, Math.min(1, ((p.x() - a.x()) * dx + (p.z() - a.z()) * dz) / lengthSq));
        return Math.hypot(a.x() + t * dx - p.x(), a.z() + t * dz - p.z());
    }
}
