package io.orchard.protocol.value;

/**
 * A point on the ground plane (X/Z), used for the outlines of the castle and the river and for
 * the entry points of bridges.
 *
 * @param x east (+) and west (-)
 * @param z south (+) and north (-)
 */
public record Point2(double x, double z) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Point2 {
        Checks.finite(x, "x");
        Checks.finite(z, "z");
    }

    /** This point at height {@code y}. */
    public Vec3 at(double y) {
        return new Vec3(x, y, z);
    }

    /** The straight-line distance to {@code other} on the ground. */
    public double distance(Point2 other) {
        double dx = other.x - x;
        double dz = other.z - z;
        return Math.sqrt(dx * dx + dz * dz); // Math.hypot guards against overflow we cannot have, slowly
    }
}
