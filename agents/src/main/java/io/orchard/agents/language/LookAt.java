package io.orchard.agents.language;

import java.util.Objects;

/**
 * Turn on the spot to face an object: "look at the castle", "face the river", "turn towards
 * Guppy". The agent does not walk; if it does not know where the object is, it turns to look for
 * it.
 *
 * @param target what to face
 */
public record LookAt(Reference target) implements Goal {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LookAt {
        Objects.requireNonNull(target, "target");
    }
}
