package io.orchard.viewer.model.build;

import io.orchard.viewer.model.build.FaceSets.Faces;
import java.util.Arrays;

/**
 * Normals that a face set leaves out: one per face by Newell's method, and smoothed across the
 * faces that meet at a point within the crease angle.
 */
final class FaceNormals {

    /** Faces around one point considered when smoothing normals, so the work stays linear. */
    static final int SMOOTHING_NEIGHBOURS = 64;

    private FaceNormals() {
    }

    /** Averages, at each corner, the normals of the faces round its point within the crease. */
    static void smooth(Faces faces, int[] coordIndex, int pointCount, float[] faceNormals,
                               double minCos, float[] result) {
        int[] start = new int[pointCount + 1];
        for (int k = 0; k < faces.corners; k++) {
            start[coordIndex[faces.cornerPosition[k]] + 1]++;
        }
        for (int p = 0; p < pointCount; p++) {
            start[p + 1] += start[p];
        }
        int[] fill = Arrays.copyOf(start, pointCount);
        int[] incident = new int[faces.corners];
        for (int f = 0; f < faces.count; f++) {
            for (int i = 0; i < faces.size[f]; i++) {
                int point = coordIndex[faces.cornerPosition[faces.firstCorner[f] + i]];
                incident[fill[point]++] = f;
            }
        }
        for (int f = 0; f < faces.count; f++) {
            for (int i = 0; i < faces.size[f]; i++) {
                int corner = faces.firstCorner[f] + i;
                int point = coordIndex[faces.cornerPosition[corner]];
                double x = 0;
                double y = 0;
                double z = 0;
                int end = Math.min(start[point + 1], start[point] + SMOOTHING_NEIGHBOURS);
                boolean sawOwn = false;
                for (int j = start[point]; j < end; j++) {
                    int g = incident[j];
                    sawOwn |= g == f;
                    double cos = faceNormals[3 * f] * faceNormals[3 * g]
                            + faceNormals[3 * f + 1] * faceNormals[3 * g + 1]
                            + faceNormals[3 * f + 2] * faceNormals[3 * g + 2];
                    if (g == f || cos >= minCos) {
                        x += faceNormals[3 * g];
                        y += faceNormals[3 * g + 1];
                        z += faceNormals[3 * g + 2];
                    }
                }
                if (!sawOwn) {
                    x += faceNormals[3 * f];
                    y += faceNormals[3 * f + 1];
                    z += faceNormals[3 * f + 2];
                }
                double length = Math.sqrt(x * x + y * y + z * z);
                if (length < 1e-12) {
                    System.arraycopy(faceNormals, 3 * f, result, 3 * corner, 3);
                } else {
                    result[3 * corner] = (float) (x / length);
                    result[3 * corner + 1] = (float) (y / length);
                    result[3 * corner + 2] = (float) (z / length);
                }
            }
        }
    }

    /** A face's unit normal by Newell's method, which tolerates slightly non-planar faces. */
    static void newell(Faces faces, int f, int[] coordIndex, float[] points, boolean ccw,
                               float[] out) {
        double x = 0;
        double y = 0;
        double z = 0;
        int n = faces.size[f];
        for (int i = 0; i < n; i++) {
            int a = 3 * coordIndex[faces.cornerPosition[faces.firstCorner[f] + i]];
            int b = 3 * coordIndex[faces.cornerPosition[faces.firstCorner[f] + (i + 1) % n]];
            x += (points[a + 1] - points[b + 1]) * (points[a + 2] + points[b + 2]);
            y += (points[a + 2] - points[b + 2]) * (points[a] + points[b]);
            z += (points[a] - points[b]) * (points[a + 1] + points[b + 1]);
        }
        double length = Math.sqrt(x * x + y * y + z * z);
        if (length < 1e-20) {
            out[3 * f + 1] = 1;
            return;
        }
        double sign = ccw ? 1 : -1;
        out[3 * f] = (float) (sign * x / length);
        out[3 * f + 1] = (float) (sign * y / length);
        out[3 * f + 2] = (float) (sign * z / length);
    }
}
