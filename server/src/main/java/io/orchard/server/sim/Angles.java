package io.orchard.server.sim;

/**
 * Angles as the protocol measures them: a heading h faces (-sin h, 0, -cos h), so north (-z) is 0
 * and angles grow turning left; bearings are relative to a heading, in (-pi, pi].
 */
final class Angles {

    private Angles() {}

    /** An angle in (-pi, pi]. */
    static double normalise(double angle) {
        // Most angles here are differences of two normalised angles: one turn brings them back.
        double a = angle > Math.PI ? angle - 2 * Math.PI : angle <= -Math.PI ? angle + 2 * Math.PI : angle;
        if (a > Math.PI || a <= -Math.PI) {
            a = Math.IEEEremainder(angle, 2 * Math.PI);
            a = a <= -Math.PI ? a + 2 * Math.PI : a;
        }
        return a;
    }

    /** The heading that faces along (dx, dz). */
    static double headingOf(double dx, double dz) {
        return atan2(-dx, -dz);
    }

    /**
     * atan2 to within about 1e-5 radians. Perception reports bearings rounded to milliradians, and
     * the exact {@link Math#atan2} was the largest single cost of a tick with a thousand agents.
     * Plain arithmetic, so it gives the same result on every JVM.
     */
    static double atan2(double y, double x) {
        double ax = Math.abs(x);
        double ay = Math.abs(y);
        if (ax == 0 && ay == 0) {
            return 0;
        }
        double a = Math.min(ax, ay) / Math.max(ax, ay);
        double s = a * a;
        double r = ((-0.0464964749 * s + 0.15931422) * s - 0.327622764) * s * a + a;
        if (ay > ax) {
            r = Math.PI / 2 - r;
        }
        if (x < 0) {
            r = Math.PI - r;
        }
        return y < 0 ? -r : r;
    }
}
