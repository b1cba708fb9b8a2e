package io.orchard.server.world;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Point2;

/**
 * The point of the river nearest to a place, and which way the river runs there: what an agent
 * perceives of the river as a landmark.
 *
 * @param point    the nearest point of the river (of its water or of a bridge over it); the place
 *                 itself when it is in the river
 * @param distance the ground distance from the place to that point; 0 in the river
 * @param heading  the direction in which the river runs at that point, as a heading in radians (0
 *                 north, positive turned to the west), folded into (-&pi;/2, &pi;/2] because a
 *                 river here has no upstream; it is the direction of the nearest stretch of bank
 */
public record RiverPoint(Point2 point, double distance, double heading) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public RiverPoint {
        Checks.present(point, "point");
        Checks.nonNegative(distance, "distance");
        Checks.finite(heading, "heading");
    }
}
