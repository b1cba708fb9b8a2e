package io.orchard.agents.language;

import io.orchard.protocol.value.Sector;
import java.util.Objects;

/**
 * Walk in a compass direction: "go north", "head south-east", "walk towards the west". North is
 * {@code -z}, as in the protocol. There is no destination: the agent walks on in that direction
 * (around obstacles) until the world's edge, the river without a bridge, or a new instruction.
 *
 * @param direction the compass direction to walk in
 */
public record Head(Sector direction) implements Goal {

    public Head {
        Objects.requireNonNull(direction, "direction");
    }
}
