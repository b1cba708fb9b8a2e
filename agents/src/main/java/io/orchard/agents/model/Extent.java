package io.orchard.agents.model;

/**
 * The box around the points of a model, as its nodes' transforms place them: 4x4 matrices in
 * column-major order, as glTF writes them.
 */
final class Extent {

    static final double[] IDENTITY = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    final double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
    final double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};

    boolean isEmpty() {
        return !(min[0] <= max[0]);
    }

    /** Takes in point (x, y, z) placed by {@code m}. */
    void add(double[] m, double x, double y, double z) {
        double[] p = {
            m[0] * x + m[4] * y + m[8] * z + m[12],
            m[1] * x + m[5] * y + m[9] * z + m[13],
            m[2] * x + m[6] * y + m[10] * z + m[14],
        };
        for (int a = 0; a < 3; a++) {
            if (Double.isFinite(p[a])) {
                min[a] = Math.min(min[a], p[a]);
                max[a] = Math.max(max[a], p[a]);
            }
        }
    }

    /** Takes in the eight corners of the box from {@code low} to {@code high}, placed by {@code m}. */
    void addBox(double[] m, double[] low, double[] high) {
        for (int corner = 0; corner < 8; corner++) {
            add(m, (corner & 1) == 0 ? low[0] : high[0], (corner & 2) == 0 ? low[1] : high[1],
                    (corner & 4) == 0 ? low[2] : high[2]);
        }
    }

    static double[] multiply(double[] a, double[] b) {
        double[] out = new double[16];
        for (int column = 0; column < 4; column++) {
            for (int row = 0; row < 4; row++) {
                double sum = 0;
                for (int k = 0; k < 4; k++) {
                    sum += a[k * 4 + row] * b[column * 4 + k];
                }
                out[column * 4 + row] = sum;
            }
        }
        return out;
    }

    /** Translation, then rotation by the unit quaternion (qx, qy, qz, qw), then scale, as glTF composes them. */
    static double[] trs(double[] t, double[] q, double[] s) {
        double x = q[0];
        double y = q[1];
        double z = q[2];
        double w = q[3];
        double n = Math.sqrt(x * x + y * y + z * z + w * w);
        if (n > 0) {
            x /= n;
            y /= n;
            z /= n;
            w /= n;
        }
        return new double[] {
            (1 - 2 * (y * y + z * z)) * s[0], 2 * (x * y + z * w) * s[0], 2 * (x * z - y * w) * s[0], 0,
            2 * (x * y - z * w) * s[1], (1 - 2 * (x * x + z * z)) * s[1], 2 * (y * z + x * w) * s[1], 0,
            2 * (x * z + y * w) * s[2], 2 * (y * z - x * w) * s[2], (1 - 2 * (x * x + y * y)) * s[2], 0,
            t[0], t[1], t[2], 1,
        };
    }

    /** The quaternion of a rotation by {@code angle} radians about the axis (x, y, z). */
    static double[] axisAngle(double x, double y, double z, double angle) {
        double length = Math.sqrt(x * x + y * y + z * z);
        if (length == 0) {
            return new double[] {0, 0, 0, 1};
        }
        double sin = Math.sin(angle / 2) / length;
        return new double[] {x * sin, y * sin, z * sin, Math.cos(angle / 2)};
    }
}
