package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Sector;
import java.util.Objects;

/**
 * Walk in a compass direction: "go north", "head south-east", "walk 20 metres to the west". North
 * is {@code -z}, as in the protocol. Without a distance the agent walks on in that direction
 * (around obstacles) until the world's edge, the river without a bridge, or a new instruction.
 *
 * @param direction the compass direction to walk in
 * @param distance  how far, in world units (a metre each), or null for as far as it goes
 */
public record Head(Sector direction, @Nullable Double distance) implements Goal {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Head {
        Objects.requireNonNull(direction, "direction");
        RelativeMove.checkDistance(distance);
    }

    /** Walk on in a compass direction, as far as it goes. */
    public Head(Sector direction) {
        this(direction, null);
    }
}
