package io.orchard.agents.language;

import io.orchard.protocol.value.Sector;
import java.util.Objects;

/**
 * Turn on the spot to face a compass direction: "face north", "look east", "turn to the south".
 * North is {@code -z}, as in the protocol.
 *
 * @param direction the compass direction to face
 */
public record Face(Sector direction) implements Goal {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Face {
        Objects.requireNonNull(direction, "direction");
    }
}
