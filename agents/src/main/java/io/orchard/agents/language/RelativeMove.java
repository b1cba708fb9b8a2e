package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;
import java.util.Locale;
import java.util.Objects;

/**
 * Walk relative to where the agent is facing: "go forward", "step back", "go left 5 metres",
 * "move straight ahead". Without a distance how far is up to the agent (a few body lengths);
 * turning is not needed for {@link Direction#BACKWARD}, which walks backwards.
 *
 * @param direction which way, relative to the agent's heading
 * @param distance  how far, in world units (a metre each), or null for a few steps
 */
public record RelativeMove(Direction direction, @Nullable Double distance) implements Goal {

    /** The longest walk one instruction may ask for: farther than across any world Orchard makes. */
    public static final double MAX_DISTANCE = 1000;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RelativeMove {
        Objects.requireNonNull(direction, "direction");
        checkDistance(distance);
    }

    /** Walk a few steps that way. */
    public RelativeMove(Direction direction) {
        this(direction, null);
    }

    /** How a distance reads in the agent's answers: "1 metre", "20 metres", "2.5 metres". */
    public static String metres(double distance) {
        String number = Notation.number(distance);
        return number + (number.equals("1") ? " metre" : " metres");
    }

    static void checkDistance(Double distance) {
        if (distance != null && !(distance > 0 && distance <= MAX_DISTANCE)) {
            throw new IllegalArgumentException("distance must be more than 0 and at most " + (int) MAX_DISTANCE
                    + " units, was " + distance);
        }
    }

    /** A direction relative to the agent's heading. */
    public enum Direction {
        /** The way the agent faces. */
        FORWARD,
        /** Opposite to the way the agent faces. */
        BACKWARD,
        /** To the agent's left. */
        LEFT,
        /** To the agent's right. */
        RIGHT;

        /** The name of this direction in JSON and in the notation: {@code forward}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }
}
