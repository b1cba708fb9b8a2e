package io.orchard.viewer.world;

import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;

/**
 * Plane geometry on the ground (x, z) for simple polygons such as the castle's footprint and the
 * river's outline: area, containment, segment crossings and triangulation by ear clipping.
 */
public final class Polygons {

    private Polygons() {
    }

    /**
     * The signed area, positive when the points run counter-clockwise seen from above with x to
     * the east and z to the south (that is, clockwise in the (x, z) plane's own orientation).
     */
    public static double signedArea(List<Point2> polygon) {
        double twice = 0;
        int n = polygon.size();
        for (int i = 0; i < n; i++) {
            Point2 a = polygon.get(i);
            Point2 b = polygon.get((i + 1) % n);
            twice += a.x() * b.z() - b.x() * a.z();
        }
        return twice / 2;
    }

    /** Whether the point lies inside the polygon (even-odd rule; points on an edge may go either way). */
    public static boolean contains(List<Point2> polygon, double x, double z) {
        boolean inside = false;
        int n = polygon.size();
        for (int i = 0, j = n - 1; i < n; j = i++) {
            Point2 a = polygon.get(i);
            Point2 b = polygon.get(j);
            if ((a.z() > z) != (b.z() > z)
                    && x < (b.x() - a.x()) * (z - a.z()) / (b.z() - a.z()) + a.x()) {
                inside = !inside;
            }
        }
        return inside;
    }

    /** Whether the segment from a to b crosses an edge of the polygon or runs inside it. */
    public static boolean segmentTouches(List<Point2> polygon, double ax, double az, double bx, double bz) {
        int n = polygon.size();
        for (int i = 0; i < n; i++) {
            Point2 p = polygon.get(i);
            Point2 q = polygon.get((i + 1) % n);
            if (segmentsCross(ax, az, bx, bz, p.x(), p.z(), q.x(), q.z())) {
                return true;
            }
        }
        return contains(polygon, (ax + bx) / 2, (az + bz) / 2);
    }

    /** Whether two closed segments share a point. */
    public static boolean segmentsCross(double ax, double az, double bx, double bz,
                                        double cx, double cz, double dx, double dz) {
        double d1 = cross(cx, cz, dx, dz, ax, az);
        double d2 = cross(cx, cz, dx, dz, bx, bz);
        double d3 = cross(ax, az, bx, bz, cx, cz);
        double d4 = cross(ax, az, bx, bz, dx, dz);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
            return true;
        }
        return (d1 == 0 && onSegment(cx, cz, dx, dz, ax, az))
                || (d2 == 0 && onSegment(cx, cz, dx, dz, bx, bz))
                || (d3 == 0 && onSegment(ax, az, bx, bz, cx, cz))
                || (d4 == 0 && onSegment(ax, az, bx, bz, dx, dz));
    }

    /**
     * Triangulates a simple polygon by ear clipping.
     *
     * @return indices into {@code polygon}, three per triangle, every triangle wound like the
     *         polygon; {@code n - 2} triangles for {@code n} points
     * @throws IllegalArgumentException when the polygon has fewer than 3 points or is not simple
     *                                  enough to clip (self-intersecting)
     */
    public static int[] triangulate(List<Point2> polygon) {
        int n = polygon.size();
        if (n < 3) {
            throw new IllegalArgumentException("a polygon needs at least 3 points, has " + n);
        }
        boolean counterClockwise = signedArea(polygon) > 0;
        List<Integer> left = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            left.add(i);
        }
        int[] triangles = new int[(n - 2) * 3];
        int written = 0;
        int guard = 0;
        int i = 0;
        while (left.size() > 3) {
            int size = left.size();
            int prev = left.get((i + size - 1) % size);
            int here = left.get(i % size);
            int next = left.get((i + 1) % size);
            if (isEar(polygon, left, prev, here, next, counterClockwise)) {
                triangles[written++] = prev;
                triangles[written++] = here;
                triangles[written++] = next;
                left.remove(i % size);
                guard = 0;
            } else {
                i++;
                if (++guard > size) {
                    // No ear left: the outline crosses itself or has collinear spikes. Clip the
                    // flattest corner anyway, so that a slightly degenerate outline still shows.
                    int flattest = flattestCorner(polygon, left);
                    int s = left.size();
                    triangles[written++] = left.get((flattest + s - 1) % s);
                    triangles[written++] = left.get(flattest);
                    triangles[written++] = left.get((flattest + 1) % s);
                    left.remove(flattest);
                    guard = 0;
                }
            }
        }
        triangles[written++] = left.get(0);
        triangles[written++] = left.get(1);
        triangles[written] = left.get(2);
        return triangles;
    }

    /** The centre of the polygon's area. */
    public static Point2 centroid(List<Point2> polygon) {
        double area = signedArea(polygon);
        if (Math.abs(area) < 1e-12) {
            double x = 0;
            double z = 0;
            for (Point2 p : polygon) {
                x += p.x();
                z += p.z();
            }
            return new Point2(x / polygon.size(), z / polygon.size());
        }
        double cx = 0;
        double cz = 0;
        int n = polygon.size();
        for (int i = 0; i < n; i++) {
            Point2 a = polygon.get(i);
            Point2 b = polygon.get((i + 1) % n);
            double f = a.x() * b.z() - b.x() * a.z();
            cx += (a.x() + b.x()) * f;
            cz += (a.z() + b.z()) * f;
        }
        return new Point2(cx / (6 * area), cz / (6 * area));
    }

    /** The corners of the convex hull of the points, in order around it. */
    public static List<Point2> convexHull(List<Point2> points) {
        List<Point2> sorted = new ArrayList<>(points);
        sorted.sort((a, b) -> a.x() != b.x() ? Double.compare(a.x(), b.x()) : Double.compare(a.z(), b.z()));
        List<Point2> lower = halfHull(sorted);
        java.util.Collections.reverse(sorted);
        List<Point2> upper = halfHull(sorted);
        lower.remove(lower.size() - 1);
        upper.remove(upper.size() - 1);
        lower.addAll(upper);
        return lower;
    }

    private static List<Point2> halfHull(List<Point2> sorted) {
        List<Point2> hull = new ArrayList<>();
        for (Point2 p : sorted) {
            while (hull.size() >= 2) {
                Point2 a = hull.get(hull.size() - 2);
                Point2 b = hull.get(hull.size() - 1);
                if (cross(a.x(), a.z(), b.x(), b.z(), p.x(), p.z()) > 0) {
                    break;
                }
                hull.remove(hull.size() - 1);
            }
            hull.add(p);
        }
        return hull;
    }

    private static boolean isEar(List<Point2> polygon, List<Integer> left, int prev, int here, int next,
                                 boolean counterClockwise) {
        Point2 a = polygon.get(prev);
        Point2 b = polygon.get(here);
        Point2 c = polygon.get(next);
        double turn = cross(a.x(), a.z(), b.x(), b.z(), c.x(), c.z());
        if (counterClockwise ? turn <= 0 : turn >= 0) {
            return false;
        }
        for (int index : left) {
            if (index == prev || index == here || index == next) {
                continue;
            }
            Point2 p = polygon.get(index);
            if (inTriangle(p, a, b, c)) {
                return false;
            }
        }
        return true;
    }

    private static int flattestCorner(List<Point2> polygon, List<Integer> left) {
        int best = 0;
        double smallest = Double.MAX_VALUE;
        int s = left.size();
        for (int k = 0; k < s; k++) {
            Point2 a = polygon.get(left.get((k + s - 1) % s));
            Point2 b = polygon.get(left.get(k));
            Point2 c = polygon.get(left.get((k + 1) % s));
            double area = Math.abs(cross(a.x(), a.z(), b.x(), b.z(), c.x(), c.z()));
            if (area < smallest) {
                smallest = area;
                best = k;
            }
        }
        return best;
    }

    private static boolean inTriangle(Point2 p, Point2 a, Point2 b, Point2 c) {
        double d1 = cross(a.x(), a.z(), b.x(), b.z(), p.x(), p.z());
        double d2 = cross(b.x(), b.z(), c.x(), c.z(), p.x(), p.z());
        double d3 = cross(c.x(), c.z(), a.x(), a.z(), p.x(), p.z());
        boolean negative = d1 < 0 || d2 < 0 || d3 < 0;
        boolean positive = d1 > 0 || d2 > 0 || d3 > 0;
        return !(negative && positive);
    }

    private static double cross(double ax, double az, double bx, double bz, double px, double pz) {
        return (bx - ax) * (pz - az) - (bz - az) * (px - ax);
    }

    private static boolean onSegment(double ax, double az, double bx, double bz, double px, double pz) {
        return Math.min(ax, bx) <= px && px <= Math.max(ax, bx) && Math.min(az, bz) <= pz && pz <= Math.max(az, bz);
    }
}
