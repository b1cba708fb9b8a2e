package io.orchard.server.world;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;

/**
 * A tree, as in the paper a bounding cylinder: its crown's radius and the tree's height. Only the
 * trunk blocks movement, so agents walk under the crown; fruit hangs under the crown, beside the
 * trunk.
 *
 * <p>The trunk is not part of the cylinder that perception and scenario files carry, so it follows
 * from the crown by one rule: {@link #TRUNK_SHARE} of the crown's radius, but at least
 * {@link #MIN_TRUNK_RADIUS} and at most {@link #MAX_TRUNK_RADIUS}, and never wider than the crown.
 * A crown of radius 2 has a trunk of radius 0.3.
 *
 * @param id          the tree's id, {@code T1}, {@code T2}...
 * @param position    the centre of the trunk on the ground
 * @param crownRadius the radius of the bounding cylinder, that is of the crown
 * @param height      the height of the tree's top
 */
public record Tree(String id, Point2 position, double crownRadius, double height) {

    /** A trunk's radius as a share of its crown's radius, before the limits. */
    public static final double TRUNK_SHARE = 0.15;

    /** The thinnest trunk, in units. */
    public static final double MIN_TRUNK_RADIUS = 0.2;

    /** The thickest trunk, in units. */
    public static final double MAX_TRUNK_RADIUS = 0.5;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Tree {
        Checks.id(id, "id");
        Checks.present(position, "position");
        Checks.positive(crownRadius, "radius");
        Checks.positive(height, "height");
    }

    /** The tree a tree obstacle describes. */
    public static Tree of(Obstacle obstacle) {
        if (obstacle.kind() != ObjectKind.TREE) {
            throw new IllegalArgumentException(obstacle.id() + " is a " + obstacle.kind().wireName() + ", not a tree");
        }
        return new Tree(obstacle.id(), obstacle.position(), obstacle.radius(), obstacle.height());
    }

    /** The trunk radius the rule gives for a crown radius. */
    public static double trunkRadius(double crownRadius) {
        double share = Math.max(MIN_TRUNK_RADIUS, Math.min(MAX_TRUNK_RADIUS, crownRadius * TRUNK_SHARE));
        return Math.min(crownRadius, share);
    }

    /** The radius of the trunk: the circle agents cannot enter. */
    public double trunkRadius() {
        return trunkRadius(crownRadius);
    }

    /** This tree as the protocol describes it. */
    public Obstacle obstacle() {
        return new Obstacle(id, ObjectKind.TREE, position, crownRadius, height);
    }
}
