package io.orchard.server.sim;

import io.orchard.protocol.value.Vec3;

/**
 * The precision of what an agent perceives: lengths rounded to centimetres and angles to
 * milliradians. Agents perceive vaguely anyway, and shorter numbers halve the cost of sending a
 * perception.
 */
final class Precision {

    private Precision() {}

    /** A length rounded to hundredths of a unit. */
    static double length(double value) {
        return Math.round(value * 100) / 100.0;
    }

    /** An angle in (-π, π] rounded to thousandths of a radian, staying in (-π, π]. */
    static double angle(double value) {
        double rounded = Math.round(value * 1000) / 1000.0;
        return rounded <= -Math.PI ? rounded + 0.001 : Math.min(rounded, Math.PI);
    }

    /** A point with each coordinate rounded as a length. */
    static Vec3 position(Vec3 v) {
        return new Vec3(length(v.x()), length(v.y()), length(v.z()));
    }
}
