package io.orchard.server.sim;

import io.orchard.protocol.value.Vec3;

/**
 * An agent walking a straight segment at constant speed, as viewers interpolate it.
 *
 * @param from      where the walk starts
 * @param to        where it ends
 * @param startTime simulated time at {@code from}
 * @param duration  simulated seconds to {@code to}
 */
record Motion(Vec3 from, Vec3 to, double startTime, double duration) {

    /** Where the walker is at simulated time {@code time}. */
    Vec3 positionAt(double time) {
        if (duration <= 0 || time >= startTime + duration) {
            return to;
        }
        double f = Math.max(0, (time - startTime) / duration);
        return new Vec3(from.x() + (to.x() - from.x()) * f, 0, from.z() + (to.z() - from.z()) * f);
    }

    boolean finishedAt(double time) {
        return time >= startTime + duration - 1e-9;
    }
}
