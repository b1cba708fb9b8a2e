package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;

/**
 * Headings and bearings as the protocol defines them: a heading {@code h} faces
 * {@code (-sin h, 0, -cos h)} (0 is north, positive turns left), and a bearing is measured from the
 * heading, positive to the left, in (-pi, pi].
 *
 * <pre>{@code
 * Point2 tree = Bearings.toWorld(me, heading, perceivedTree.at()); // where the tree stands
 * double turn = Bearings.headingTowards(me, tree);                 // the heading that faces it
 * }</pre>
 */
public final class Bearings {

    private Bearings() {}

    /** The angle reduced to (-pi, pi]. */
    public static double normalise(double angle) {
        double a = Math.IEEEremainder(angle, 2 * Math.PI);
        return a <= -Math.PI ? a + 2 * Math.PI : a;
    }

    /** The heading that faces the direction (dx, dz), in (-pi, pi]. */
    public static double headingOf(double dx, double dz) {
        return normalise(Math.atan2(-dx, -dz));
    }

    /** The heading that faces {@code to} from {@code from}. */
    public static double headingTowards(Point2 from, Point2 to) {
        return headingOf(to.x() - from.x(), to.z() - from.z());
    }

    /** The bearing of {@code target} for an agent at {@code self} with this heading, in (-pi, pi]. */
    public static double bearing(Point2 self, double heading, Point2 target) {
        return normalise(headingTowards(self, target) - heading);
    }

    /**
     * Where a perceived thing is in the world.
     *
     * @param self    the perceiver's position (its perception's {@code position})
     * @param heading the perceiver's heading (its perception's {@code heading})
     * @param at      the thing's distance and bearing as perceived
     */
    public static Point2 toWorld(Point2 self, double heading, RelativePosition at) {
        double a = heading + at.bearing();
        return new Point2(self.x() - at.distance() * Math.sin(a), self.z() - at.distance() * Math.cos(a));
    }

    /** The distance and bearing at which an agent at {@code self} with this heading perceives {@code target}. */
    public static RelativePosition toRelative(Point2 self, double heading, Point2 target) {
        double distance = self.distance(target);
        return new RelativePosition(distance, distance == 0 ? 0 : bearing(self, heading, target));
    }

    /** The point {@code distance} units from {@code from} in the direction of {@code heading}. */
    public static Point2 ahead(Point2 from, double heading, double distance) {
        return new Point2(from.x() - distance * Math.sin(heading), from.z() - distance * Math.cos(heading));
    }
}
