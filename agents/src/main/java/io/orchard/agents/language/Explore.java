package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;

/**
 * Explore, looking at parts of the world not seen lately: "explore", "explore the forest", "look
 * around the castle", "explore the other side of the river". Exploring has no end of its own; it
 * lasts until a new instruction, or, inside a {@link Sequence}, until the area has been looked
 * over once.
 *
 * @param area where to explore: the forest, a {@linkplain Reference.Kind#PLACE place}, or an
 *             object whose surroundings are meant; null for anywhere
 */
public record Explore(@Nullable Reference area) implements Goal {

    /** Explore anywhere. */
    public static Explore anywhere() {
        return new Explore(null);
    }
}
