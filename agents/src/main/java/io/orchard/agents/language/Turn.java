package io.orchard.agents.language;

/**
 * Turn on the spot by an angle: "turn left" (+90 degrees), "turn right" (-90), "turn around"
 * (180), "turn 45 degrees to the right" (-45). Angles follow the protocol's headings: a positive
 * angle turns the agent to its left (counter-clockwise seen from above).
 *
 * @param radians the angle to turn by; positive turns left
 */
public record Turn(double radians) implements Goal {

    /** @throws IllegalArgumentException when the angle is not finite */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Turn {
        if (!Double.isFinite(radians)) {
            throw new IllegalArgumentException("radians must be finite, was " + radians);
        }
    }

    /** A turn by this many degrees; positive turns left. */
    public static Turn degrees(double degrees) {
        return new Turn(Math.toRadians(degrees));
    }

    /** A quarter turn to the left. */
    public static Turn left() {
        return degrees(90);
    }

    /** A quarter turn to the right. */
    public static Turn right() {
        return degrees(-90);
    }

    /** A half turn. */
    public static Turn around() {
        return degrees(180);
    }

    /** The angle in degrees, positive to the left. */
    public double degrees() {
        return Math.toDegrees(radians);
    }
}
