package io.orchard.agents.map;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Point2;

/**
 * A circle on the ground: what blocks walking (a trunk, a table, another agent) or an area known
 * to be dry land.
 *
 * @param x      its centre, east
 * @param z      its centre, south
 * @param radius its radius, not negative
 */
public record Circle(double x, double z, double radius) {

    /** Checks that the centre is finite and the radius not negative. */
    public Circle {
        Checks.finite(x, "x");
        Checks.finite(z, "z");
        Checks.nonNegative(radius, "radius");
    }

    /** A circle around a point. */
    public static Circle around(Point2 centre, double radius) {
        return new Circle(centre.x(), centre.z(), radius);
    }

    /** Its centre. */
    public Point2 centre() {
        return new Point2(x, z);
    }

    /** Whether the point lies inside (or on) the circle. */
    public boolean contains(double px, double pz) {
        double dx = px - x;
        double dz = pz - z;
        return dx * dx + dz * dz <= radius * radius;
    }

    /** The smallest distance between this circle's centre and the segment from a to b. */
    public double distanceToSegment(Point2 a, Point2 b) {
        return segmentDistance(a.x(), a.z(), b.x(), b.z(), x, z);
    }

    /** The distance from point (px, pz) to the segment (ax, az)-(bx, bz). */
    static double segmentDistance(double ax, double az, double bx, double bz, double px, double pz) {
        double dx = bx - ax;
        double dz = bz - az;
        double lengthSq = dx * dx + dz * dz;
        double t = lengthSq == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * dx + (pz - az) * dz) / lengthSq));
        return Math.hypot(ax + t * dx - px, az + t * dz - pz);
    }
}
