package io.orchard.protocol.value;

import java.util.List;

/**
 * The castle: the 2D projection of its shape onto the X/Z plane, extruded to its wall height.
 *
 * @param footprint the outline as a simple polygon, at least three points, not repeated at the end
 * @param height    the height of its walls
 */
public record CastleShape(List<Point2> footprint, double height) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public CastleShape {
        footprint = Checks.list(footprint, "footprint");
        if (footprint.size() < 3) {
            throw new IllegalArgumentException("footprint must have at least 3 points, had " + footprint.size());
        }
        Checks.positive(height, "height");
    }
}
