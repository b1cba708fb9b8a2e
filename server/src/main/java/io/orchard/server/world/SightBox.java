package io.orchard.server.world;

/**
 * The smallest ground rectangle around what an agent can see: the sector of a circle of its range,
 * centred on its heading and as wide as its field of view. The broad phase of perception visits the
 * grid cells under this box rather than under the square around the whole circle, which for a 120°
 * field is less than half of them.
 *
 * <p>Angles are the protocol's: a heading h faces (-sin h, -cos h) on the ground.
 *
 * @param minX west edge
 * @param minZ north edge
 * @param maxX east edge
 * @param maxZ south edge
 */
public record SightBox(double minX, double minZ, double maxX, double maxZ) {

    /** Keeps points on the sector's edge inside despite rounding in the sines and cosines. */
    private static final double MARGIN = 1e-6;

    /** The box around the whole circle of {@code range} around (x, z). */
    public static SightBox around(double x, double z, double range) {
        return new SightBox(x - range, z - range, x + range, z + range);
    }

    /**
     * The box around the sector seen from (x, z) facing {@code heading}, {@code fieldOfView} wide
     * (radians; 2π or more is the whole circle) and {@code range} deep.
     */
    public static SightBox of(double x, double z, double range, double heading, double fieldOfView) {
        double half = fieldOfView / 2;
        if (half >= Math.PI) {
            return around(x, z, range);
        }
        double facingX = -Math.sin(heading);
        double facingZ = -Math.cos(heading);
        double cos = Math.cos(half);
        double sin = Math.sin(half);
        // The apex and the two ends of the arc...
        double leftX = facingX * cos - facingZ * sin;
        double leftZ = facingX * sin + facingZ * cos;
        double rightX = facingX * cos + facingZ * sin;
        double rightZ = -facingX * sin + facingZ * cos;
        double minX = Math.min(0, Math.min(leftX, rightX));
        double maxX = Math.max(0, Math.max(leftX, rightX));
        double minZ = Math.min(0, Math.min(leftZ, rightZ));
        double maxZ = Math.max(0, Math.max(leftZ, rightZ));
        // ...and the arc's extremes along each axis that the field takes in.
        if (facingX >= cos) {
            maxX = 1;
        }
        if (-facingX >= cos) {
            minX = -1;
        }
        if (facingZ >= cos) {
            maxZ = 1;
        }
        if (-facingZ >= cos) {
            minZ = -1;
        }
        double margin = MARGIN * Math.max(1, range);
        return new SightBox(x + minX * range - margin, z + minZ * range - margin, x + maxX * range + margin,
                z + maxZ * range + margin);
    }

    /** Whether (x, z) lies in the box, edges included. */
    public boolean contains(double x, double z) {
        return x >= minX && x <= maxX && z >= minZ && z <= maxZ;
    }
}
