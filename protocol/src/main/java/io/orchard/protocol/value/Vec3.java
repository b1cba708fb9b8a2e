package io.orchard.protocol.value;

/**
 * A point or direction in world coordinates. As in VRML, {@code y} is up and the ground is the
 * X/Z plane; north is {@code -z} and east is {@code +x}. One unit is about one metre.
 *
 * @param x east (+) and west (-)
 * @param y height above the ground
 * @param z south (+) and north (-)
 */
public record Vec3(double x, double y, double z) {

    /** The origin. */
    public static final Vec3 ZERO = new Vec3(0, 0, 0);

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Vec3 {
        Checks.finite(x, "x");
        Checks.finite(y, "y");
        Checks.finite(z, "z");
    }

    /** A point on the ground. */
    public static Vec3 ground(double x, double z) {
        return new Vec3(x, 0, z);
    }

    /** Distance to {@code other} in the X/Z plane, ignoring height (the world is 2.5D). */
    public double groundDistance(Vec3 other) {
        double dx = other.x - x;
        double dz = other.z - z;
        return Math.sqrt(dx * dx + dz * dz); // Math.hypot guards against overflow we cannot have, slowly
    }

    /** This vector plus {@code other}, component by component. */
    public Vec3 plus(Vec3 other) {
        return new Vec3(x + other.x, y + other.y, z + other.z);
    }

    /** This vector less {@code other}, component by component. */
    public Vec3 minus(Vec3 other) {
        return new Vec3(x - other.x, y - other.y, z - other.z);
    }

    /** This vector scaled by {@code factor}. */
    public Vec3 times(double factor) {
        return new Vec3(x * factor, y * factor, z * factor);
    }

    /** This point's projection on the ground plane. */
    public Point2 onGround() {
        return new Point2(x, z);
    }
}
