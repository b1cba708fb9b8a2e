package io.orchard.agents.language;

import java.util.Objects;

/**
 * Go to a place: "go to the castle", "walk to the big tree by the river", "go near the castle",
 * "run to the north of the castle". The goal is reached when the agent stands next to the
 * destination (for an object) or inside the area (for a {@link Reference.Kind#PLACE place}); an
 * agent reaches a destination across the river by a bridge.
 *
 * @param destination the object or area to go to
 */
public record GoTo(Reference destination) implements Goal {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GoTo {
        Objects.requireNonNull(destination, "destination");
    }
}
