package io.orchard.server.sim;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Sight;

/**
 * The server's caps on an agent's body. A registration asking for more gets the cap, and the
 * {@code Registered} answer says what is in force, so no agent can out-run or out-see the rules.
 *
 * @param minRadius   smallest body radius
 * @param maxRadius   largest body radius
 * @param maxHeight   tallest body
 * @param maxSpeed    top speed in units per simulated second (the paper's 20)
 * @param maxReach    longest horizontal gripper reach
 * @param maxGripHeight highest a gripper may reach
 * @param maxRange    longest perception range
 */
public record BodyLimits(double minRadius, double maxRadius, double maxHeight, double maxSpeed, double maxReach,
                         double maxGripHeight, double maxRange) {

    /** Radius 0.2–2, height up to 4, speed up to 20, reach up to 2.5, grip up to 4 high, sight up to 60. */
    public static final BodyLimits DEFAULT = new BodyLimits(0.2, 2.0, 4.0, 20.0, 2.5, 4.0, 60.0);

    /** The body in force for one that asked for {@code asked}. */
    public Body cap(Body asked) {
        Gripper g = asked.gripper();
        double top = Math.min(g.maxHeight(), maxGripHeight);
        Gripper gripper = new Gripper(g.part(), Math.min(g.reach(), maxReach), Math.min(g.minHeight(), top), top);
        Sight sight = new Sight(Math.min(asked.sight().range(), maxRange), asked.sight().fieldOfView());
        return new Body(clamp(asked.radius(), minRadius, maxRadius), Math.min(asked.height(), maxHeight),
                Math.min(asked.maxSpeed(), maxSpeed), gripper, sight);
    }

    private static double clamp(double value, double min, double max) {
        return Math.max(min, Math.min(max, value));
    }
}
