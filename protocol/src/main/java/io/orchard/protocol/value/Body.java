package io.orchard.protocol.value;

/**
 * An agent's physical characteristics, as the server models them: a vertical cylinder that moves
 * at up to {@code maxSpeed}, a gripper and a view cone. The server caps each value at its
 * documented limits and answers a registration with the body in force.
 *
 * @param radius   radius of the agent's bounding cylinder
 * @param height   height of the agent
 * @param maxSpeed top speed in units per simulated second (the server allows at most 20)
 * @param gripper  what the agent collects fruit with
 * @param sight    how far and how wide the agent perceives
 */
public record Body(double radius, double height, double maxSpeed, Gripper gripper, Sight sight) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Body {
        Checks.positive(radius, "radius");
        Checks.positive(height, "height");
        Checks.positive(maxSpeed, "maxSpeed");
        Checks.present(gripper, "gripper");
        Checks.present(sight, "sight");
    }
}
