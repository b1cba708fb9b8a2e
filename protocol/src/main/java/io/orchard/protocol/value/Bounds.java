package io.orchard.protocol.value;

/**
 * The rectangle of the ground that agents may walk on, in world coordinates.
 *
 * @param minX west edge
 * @param minZ north edge
 * @param maxX east edge
 * @param maxZ south edge
 */
public record Bounds(double minX, double minZ, double maxX, double maxZ) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Bounds {
        Checks.finite(minX, "minX");
        Checks.finite(minZ, "minZ");
        Checks.finite(maxX, "maxX");
        Checks.finite(maxZ, "maxZ");
        if (minX >= maxX || minZ >= maxZ) {
            throw new IllegalArgumentException("bounds must have minX < maxX and minZ < maxZ, was "
                    + minX + ".." + maxX + " x " + minZ + ".." + maxZ);
        }
    }

    /** The extent along x: {@code maxX - minX}. */
    public double width() {
        return maxX - minX;
    }

    /** The extent along z: {@code maxZ - minZ}. */
    public double depth() {
        return maxZ - minZ;
    }

    /** Whether the point (x, z) lies inside the rectangle or on its edge. */
    public boolean contains(double x, double z) {
        return x >= minX && x <= maxX && z >= minZ && z <= maxZ;
    }
}
