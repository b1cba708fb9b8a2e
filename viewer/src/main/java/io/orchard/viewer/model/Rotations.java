package io.orchard.viewer.model;

import com.jme3.math.Quaternion;

/** Conversions between VRML's axis-angle rotations and jME quaternions, and their slerp. */
public final class Rotations {

    private static final double EPSILON = 1e-9;

    private Rotations() {
    }

    /** The rotation stored at {@code values[offset..offset+3]}; a zero axis means none. */
    public static Quaternion fromAxisAngle(float[] values, int offset) {
        return fromAxisAngle(values[offset], values[offset + 1], values[offset + 2],
                values[offset + 3]);
    }

    /** The rotation by {@code angle} radians about the axis {@code (x, y, z)}; a zero axis means none. */
    public static Quaternion fromAxisAngle(float x, float y, float z, float angle) {
        double length = Math.sqrt((double) x * x + (double) y * y + (double) z * z);
        if (length < EPSILON) {
            return new Quaternion();
        }
        double half = angle / 2.0;
        double s = Math.sin(half) / length;
        return new Quaternion((float) (x * s), (float) (y * s), (float) (z * s),
                (float) Math.cos(half));
    }

    /** The axis-angle form {@code {x, y, z, angle}}, with a unit axis and an angle in [0, 2pi]. */
    public static float[] toAxisAngle(Quaternion q) {
        double x = q.getX();
        double y = q.getY();
        double z = q.getZ();
        double w = q.getW();
        double norm = Math.sqrt(x * x + y * y + z * z + w * w);
        if (norm < EPSILON) {
            return new float[] {0, 0, 1, 0};
        }
        x /= norm;
        y /= norm;
        z /= norm;
        w /= norm;
        double sin = Math.sqrt(x * x + y * y + z * z);
        if (sin < EPSILON) {
            return new float[] {0, 0, 1, 0};
        }
        double angle = 2 * Math.atan2(sin, w);
        return new float[] {(float) (x / sin), (float) (y / sin), (float) (z / sin),
            (float) angle};
    }

    /** Spherical interpolation from {@code a} to {@code b} along the shorter arc. */
    public static Quaternion slerp(Quaternion a, Quaternion b, float t) {
        double ax = a.getX();
        double ay = a.getY();
        double az = a.getZ();
        double aw = a.getW();
        double bx = b.getX();
        double by = b.getY();
        double bz = b.getZ();
        double bw = b.getW();
        double cos = ax * bx + ay * by + az * bz + aw * bw;
        if (cos < 0) {
            cos = -cos;
            bx = -bx;
            by = -by;
            bz = -bz;
            bw = -bw;
        }
        double wa;
        double wb;
        if (cos > 1 - 1e-6) {
            wa = 1 - t;
            wb = t;
        } else {
            double theta = Math.acos(Math.min(1, cos));
            double sin = Math.sin(theta);
            wa = Math.sin((1 - t) * theta) / sin;
            wb = Math.sin(t * theta) / sin;
        }
        Quaternion result = new Quaternion((float) (wa * ax + wb * bx), (float) (wa * ay
                + wb * by), (float) (wa * az + wb * bz), (float) (wa * aw + wb * bw));
        return result.normalizeLocal();
    }
}
