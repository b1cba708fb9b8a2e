package io.orchard.agents.language;

import java.util.Objects;

/**
 * Never go into an area, until lifted: "don't go near the river", "stay away from the castle",
 * "stay on this side of the river" (the other side is avoided), "never go into the forest". The
 * agent plans its ways around the area, explores elsewhere, and takes no fruit it would have to
 * stand in the area for; an errand whose destination lies in it is refused, naming the rule.
 *
 * @param area the area: a {@linkplain Reference.Kind#PLACE place} ("near the river"), or an object
 *             whose own area is meant (the forest, the castle)
 */
public record Avoid(Reference area) implements Rule {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Avoid {
        Objects.requireNonNull(area, "area");
        if (area.isFruit() || area.kind() == Reference.Kind.START) {
            throw new IllegalArgumentException("an area to avoid must be a place or a landmark, not "
                    + area.kind().wireName());
        }
    }
}
