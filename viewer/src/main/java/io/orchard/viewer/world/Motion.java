package io.orchard.viewer.world;

import io.orchard.protocol.value.Vec3;
import java.util.Objects;

/**
 * One straight walk of an agent, as the server announced it in {@code AgentMoved}: from
 * {@code from} to {@code to}, starting at simulated time {@code startTime} and lasting
 * {@code duration} seconds. This is the paper's PositionInterpolator driven by its TimeSensor.
 *
 * @param from      where the walk starts
 * @param to        where it ends
 * @param startTime simulated time at the start, in seconds
 * @param duration  simulated seconds the walk takes, zero or more
 */
public record Motion(Vec3 from, Vec3 to, double startTime, double duration) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Motion {
        Objects.requireNonNull(from, "from");
        Objects.requireNonNull(to, "to");
        if (!Double.isFinite(startTime)) {
            throw new IllegalArgumentException("startTime must be finite, was " + startTime);
        }
        if (!(duration >= 0) || Double.isInfinite(duration)) {
            throw new IllegalArgumentException("duration must be zero or more seconds, was " + duration);
        }
    }

    /**
     * Where the walker is at simulated time {@code time}:
     * {@code from + (to - from) * clamp((t - start) / duration, 0, 1)}.
     */
    public Vec3 at(double time) {
        double fraction = fractionAt(time);
        return new Vec3(from.x() + (to.x() - from.x()) * fraction,
                from.y() + (to.y() - from.y()) * fraction,
                from.z() + (to.z() - from.z()) * fraction);
    }

    /** How much of the walk is done at {@code time}, from 0 to 1; a walk of no duration is done at its start. */
    public double fractionAt(double time) {
        if (duration == 0) {
            return time >= startTime ? 1 : 0;
        }
        return Math.max(0, Math.min(1, (time - startTime) / duration));
    }

    /** The simulated time the walk ends. */
    public double endTime() {
        return startTime + duration;
    }
}
