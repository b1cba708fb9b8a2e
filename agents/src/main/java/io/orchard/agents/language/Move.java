package io.orchard.agents.language;

import java.util.Locale;
import java.util.Objects;

/**
 * Walk a few steps relative to where the agent is facing: "go forward", "step back", "go left",
 * "move straight ahead". How far is up to the agent (a few body lengths); turning is not needed
 * for {@link Direction#BACKWARD}, which walks backwards.
 *
 * @param direction which way, relative to the agent's heading
 */
public record Move(Direction direction) implements Goal {

    public Move {
        Objects.requireNonNull(direction, "direction");
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
