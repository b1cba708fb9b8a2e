package io.orchard.protocol.value;

/**
 * Where something is as an agent sees it: how far, and at which angle from its heading.
 *
 * @param distance ground distance from the agent's centre to the object's centre, in units
 * @param bearing  angle from the agent's heading in radians, in (-&pi;, &pi;]: 0 straight ahead,
 *                 positive to the agent's left, negative to its right
 */
public record RelativePosition(double distance, double bearing) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RelativePosition {
        Checks.nonNegative(distance, "distance");
        Checks.finite(bearing, "bearing");
        if (bearing <= -Math.PI - 1e-9 || bearing > Math.PI + 1e-9) {
            throw new IllegalArgumentException("bearing must be in (-pi, pi], was " + bearing);
        }
    }
}
