package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;

/**
 * One sighting of the river: from where the agent stood, the nearest point of the bank it saw and
 * the direction in which the river runs there. The water lies beyond {@code shore}, seen from
 * {@code from}.
 *
 * @param from         where the agent stood
 * @param shore        the nearest point of the river's bank, in world coordinates
 * @param riverHeading the direction the river runs, as a world heading (either way along it)
 */
public record ShoreSighting(Point2 from, Point2 shore, double riverHeading) {

    /** The distance from the observer to the bank. */
    public double distance() {
        return from.distance(shore);
    }
}
