package io.orchard.agents.language;

import java.util.Objects;
import java.util.Set;

/**
 * Cross to the other side of a landmark: "cross the bridge", "cross the river", "go to the other
 * side of the river", "take the nearest bridge". Crossing the river means using a bridge, the
 * nearest one unless the landmark is a particular bridge. The goal is reached when the agent
 * stands on the side opposite to the one it started on.
 *
 * @param landmark the river, a bridge or the forest
 */
public record Cross(Reference landmark) implements Goal {

    private static final Set<Reference.Kind> CROSSABLE =
            Set.of(Reference.Kind.RIVER, Reference.Kind.BRIDGE, Reference.Kind.FOREST);

    /** @throws IllegalArgumentException when the landmark is not the river, a bridge or the forest */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Cross {
        Objects.requireNonNull(landmark, "landmark");
        if (!CROSSABLE.contains(landmark.kind())) {
            throw new IllegalArgumentException("only the river, a bridge or the forest can be crossed, not "
                    + landmark.kind());
        }
    }
}
