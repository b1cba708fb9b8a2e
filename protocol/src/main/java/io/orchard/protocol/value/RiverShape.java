package io.orchard.protocol.value;

import java.util.List;

/**
 * The river: a band of water across the world, as a polygon on the ground. Agents cross it only
 * on a bridge.
 *
 * @param outline the river's outline as a simple polygon, at least three points
 */
public record RiverShape(List<Point2> outline) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RiverShape {
        outline = Checks.list(outline, "outline");
        if (outline.size() < 3) {
            throw new IllegalArgumentException("outline must have at least 3 points, had " + outline.size());
        }
    }
}
