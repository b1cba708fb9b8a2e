package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonIgnore;

/**
 * A rotation as in VRML's SFRotation: a right-handed turn of {@code angle} radians about
 * {@code axis}. An agent's heading is a rotation about the up axis {@code (0, 1, 0)}: angle 0
 * faces north ({@code -z}), a positive angle turns the agent to its left (towards west first).
 *
 * @param axis  the axis of rotation; must not be the zero vector (it need not be normalised)
 * @param angle the angle in radians
 */
public record Rotation(Vec3 axis, double angle) {

    /** The up axis, about which agents turn. */
    public static final Vec3 UP = new Vec3(0, 1, 0);

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Rotation {
        Checks.present(axis, "axis");
        Checks.finite(angle, "angle");
        if (axis.x() == 0 && axis.y() == 0 && axis.z() == 0) {
            throw new IllegalArgumentException("axis must not be the zero vector");
        }
    }

    /** A turn about the up axis: the rotation that gives an agent the heading {@code angle}. */
    public static Rotation heading(double angle) {
        return new Rotation(UP, angle);
    }

    /** Whether this rotation is about the vertical axis (up or down), as an agent's heading must be. */
    @JsonIgnore
    public boolean isAboutUpAxis() {
        return axis.x() == 0 && axis.z() == 0;
    }

    /** The heading this rotation gives, for a rotation about the up axis (a down axis turns the other way). */
    public double headingAngle() {
        if (!isAboutUpAxis()) {
            throw new IllegalStateException("not a rotation about the up axis: " + this);
        }
        return axis.y() > 0 ? angle : -angle;
    }
}
