package io.orchard.server.world;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Vec3;

/**
 * Whether an agent can grasp a fruit, the check behind the paper's grasp request. Three conditions,
 * tested in this order so that the first reason given is the one an agent cannot fix by moving:
 * <ol>
 *   <li>height: the fruit's centre, measured from the ground the agent stands on, lies within the
 *       gripper's {@code [minHeight, maxHeight]};
 *   <li>distance: the ground distance from the agent's centre to the fruit's centre is at most the
 *       body's radius plus the gripper's reach plus the fruit's radius;
 *   <li>angle: the fruit lies in front, within {@link #HALF_ANGLE_DEGREES} degrees either side of
 *       the agent's heading (a fruit straight above or below the agent's centre counts as in front).
 * </ol>
 * Paths are not checked: the trunk a fruit hangs beside does not hide it from the gripper.
 *
 * <p>{@link World#reach} runs this check for a fruit of the world.
 */
public final class Reach {

    /** How far to either side of its heading an agent can grasp, in degrees: 120 degrees in all. */
    public static final double HALF_ANGLE_DEGREES = 60;

    private static final double HALF_ANGLE = Math.toRadians(HALF_ANGLE_DEGREES);

    private Reach() {}

    /**
     * Checks a grasp.
     *
     * @param fruit    the fruit to grasp
     * @param hanging  whether it hangs in a tree (only the wording depends on it)
     * @param position where the agent stands (its centre on the ground)
     * @param heading  the agent's heading in radians: 0 north, positive turned to the left
     * @param body     the agent's body, with its gripper
     */
    static ReachResult check(Fruit fruit, boolean hanging, Vec3 position, double heading, Body body) {
        Checks.present(fruit, "fruit");
        Checks.present(position, "position");
        Checks.finite(heading, "heading");
        Checks.present(body, "body");
        Gripper gripper = body.gripper();
        double height = fruit.position().y() - position.y();
        if (!gripper.reachesHeight(height)) {
            return new ReachResult(false, "fruit " + fruit.id() + (hanging ? " hangs at " : " lies at ") + Plane.format(height) + ", gripper reaches "
                    + Plane.format(gripper.minHeight()) + "\u2013" + Plane.format(gripper.maxHeight()));
        }
        double dx = fruit.position().x() - position.x();
        double dz = fruit.position().z() - position.z();
        double distance = Math.hypot(dx, dz);
        double reach = body.radius() + gripper.reach() + fruit.radius();
        if (distance > reach + Plane.EPSILON) {
            return new ReachResult(false, "fruit " + fruit.id() + " is " + Plane.format(distance)
                    + " units away, reach is " + Plane.format(reach));
        }
        if (distance > Plane.EPSILON) {
            double bearing = Plane.normalize(Plane.heading(dx, dz) - heading);
            if (Math.abs(bearing) > HALF_ANGLE + Plane.EPSILON) {
                return new ReachResult(false, "fruit " + fruit.id() + " is " + Math.round(Math.toDegrees(Math.abs(bearing)))
                        + "\u00b0 to the " + (bearing > 0 ? "left" : "right") + " of the heading, grasp angle is \u00b1"
                        + Math.round(HALF_ANGLE_DEGREES) + "\u00b0");
            }
        }
        return new ReachResult(true, "fruit " + fruit.id() + " is within reach");
    }
}
