package io.orchard.server.world;

/**
 * Plain arithmetic on the ground plane, used where a JTS geometry would cost an allocation per call
 * (collision and perception run for every agent on every tick).
 */
final class Plane {

    /** Slack for comparisons of lengths, so that things that exactly touch do not count as overlapping. */
    static final double EPSILON = 1e-9;

    private Plane() {}

    /** The fraction t in [0, 1] at which the segment a-b comes closest to point p. */
    static double closestApproach(double ax, double az, double bx, double bz, double px, double pz) {
        double dx = bx - ax;
        double dz = bz - az;
        double lengthSq = dx * dx + dz * dz;
        double t = lengthSq == 0 ? 0 : ((px - ax) * dx + (pz - az) * dz) / lengthSq;
        return Math.max(0, Math.min(1, t));
    }

    /** Squared distance from point p to the segment a-b (a point when a equals b). */
    static double segmentPointDistanceSq(double ax, double az, double bx, double bz, double px, double pz) {
        double t = closestApproach(ax, az, bx, bz, px, pz);
        double dx = bx - ax;
        double dz = bz - az;
        double cx = ax + t * dx - px;
        double cz = az + t * dz - pz;
        return cx * cx + cz * cz;
    }

    /**
     * The first fraction t in [0, 1] at which a disc moving from a to b comes within {@code reach} of
     * point p, or NaN when it never does. Returns 0 when it starts within reach.
     */
    static double firstContact(double ax, double az, double bx, double bz, double px, double pz, double reach) {
        double fx = ax - px;
        double fz = az - pz;
        double c = fx * fx + fz * fz - reach * reach;
        if (c < 0) {
            return 0;
        }
        double dx = bx - ax;
        double dz = bz - az;
        double a = dx * dx + dz * dz;
        if (a == 0) {
            return Double.NaN;
        }
        double b = 2 * (fx * dx + fz * dz);
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return Double.NaN;
        }
        double t = (-b - Math.sqrt(discriminant)) / (2 * a);
        return t >= 0 && t <= 1 ? t : Double.NaN;
    }

    /**
     * The heading that faces along (dx, dz): 0 faces north (-z), a positive heading is turned to
     * the left, so west is +&pi;/2, as in {@code io.orchard.protocol.value.Rotation}.
     */
    static double heading(double dx, double dz) {
        return Math.atan2(-dx, -dz);
    }

    /** An angle folded into (-&pi;, &pi;]. */
    static double normalize(double angle) {
        double folded = Math.IEEEremainder(angle, 2 * Math.PI);
        return folded <= -Math.PI ? folded + 2 * Math.PI : folded;
    }

    /** A length for people: one decimal when that is exact, else two ("2.4", "0.0", "1.25"). */
    static String format(double value) {
        double rounded = Math.round(value * 100) / 100.0;
        if (Math.abs(rounded * 10 - Math.rint(rounded * 10)) < 1e-6) {
            return String.format(java.util.Locale.ROOT, "%.1f", rounded);
        }
        return String.format(java.util.Locale.ROOT, "%.2f", rounded);
    }

    /** A point for people: "(12.5, -3.0)". */
    static String format(double x, double z) {
        return "(" + format(x) + ", " + format(z) + ")";
    }
}
