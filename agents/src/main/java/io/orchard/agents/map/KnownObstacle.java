package io.orchard.agents.map;

import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Point2;

/**
 * A tree or a table the agent has seen, in world coordinates.
 *
 * <p>Perception gives the bounding cylinder (a tree's crown, a table's top); only a tree's trunk
 * blocks walking, and its radius follows from the crown by the world's rule: 15 % of the crown's
 * radius, at least 0.2 and at most 0.5, never more than the crown's. A table blocks with its whole
 * top.
 *
 * @param id       the object's id ({@code T17}, {@code D2})
 * @param kind     tree or table
 * @param centre   the centre of its cylinder on the ground
 * @param radius   the cylinder's radius (crown or top)
 * @param height   the cylinder's height
 * @param accuracy the distance from which it was last placed: nearer sightings place it better
 * @param margin   extra room the agent keeps from it, grown when a move past it was rejected
 */
public record KnownObstacle(String id, ObjectKind kind, Point2 centre, double radius, double height,
                            double accuracy, double margin) {

    /** A trunk's radius as a share of its crown's. */
    public static final double TRUNK_SHARE = 0.15;

    /** The thinnest trunk. */
    public static final double MIN_TRUNK = 0.2;

    /** The thickest trunk. */
    public static final double MAX_TRUNK = 0.5;

    /** The radius of the circle that blocks walking: the trunk's for a tree, the top's for a table. */
    public double blockRadius() {
        return blockRadius(kind, radius);
    }

    /**
     * The radius of the circle that blocks walking for a tree or table of this kind and cylinder
     * radius (as perception gives it).
     */
    public static double blockRadius(ObjectKind kind, double radius) {
        if (kind == ObjectKind.TABLE) {
            return radius;
        }
        return Math.min(radius, Math.max(MIN_TRUNK, Math.min(MAX_TRUNK, radius * TRUNK_SHARE)));
    }

    /** The blocking circle grown by an agent's radius and this obstacle's margin. */
    public Circle blocking(double agentRadius) {
        return new Circle(centre.x(), centre.z(), blockRadius() + agentRadius + margin);
    }

    /** Whether it is a tree. */
    public boolean isTree() {
        return kind == ObjectKind.TREE;
    }

    KnownObstacle placedAt(Point2 newCentre, double newAccuracy) {
        return new KnownObstacle(id, kind, newCentre, radius, height, newAccuracy, margin);
    }

    KnownObstacle withMargin(double newMargin) {
        return new KnownObstacle(id, kind, centre, radius, height, accuracy, newMargin);
    }
}
