package io.orchard.protocol.value;

/**
 * The body part an agent collects fruit with, and where it reaches. A fruit can be grasped when it
 * lies in front of the agent no farther than {@code reach} from the agent's edge, at a height
 * between {@code minHeight} and {@code maxHeight}.
 *
 * @param part      the name of the body part, for people ("hands", "mouth", "claw")
 * @param reach     horizontal reach beyond the body's radius, in units
 * @param minHeight lowest height the gripper reaches
 * @param maxHeight highest height the gripper reaches
 */
public record Gripper(String part, double reach, double minHeight, double maxHeight) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Gripper {
        Checks.name(part, "part");
        Checks.positive(reach, "reach");
        Checks.nonNegative(minHeight, "minHeight");
        Checks.finite(maxHeight, "maxHeight");
        if (maxHeight < minHeight) {
            throw new IllegalArgumentException("maxHeight must not be below minHeight (" + minHeight + "), was "
                    + maxHeight);
        }
    }

    /** Whether a height is within this gripper's range. */
    public boolean reachesHeight(double height) {
        return height >= minHeight && height <= maxHeight;
    }
}
