package io.orchard.viewer.scene;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import io.orchard.protocol.value.Point2;
import io.orchard.viewer.world.Polygons;
import java.util.ArrayList;
import java.util.List;

/**
 * Meshes the standard shapes do not offer: a footprint extruded upwards (castle walls), a flat
 * polygon (the river), an upright cylinder or cone standing on the ground, a flat sector (a view
 * cone), a ring, and a curved tapering tube (a banana). Faces are flat-shaded and wound so that
 * their front faces outwards.
 */
public final class Meshes {

    private Meshes() {
    }

    /** A footprint extruded from height {@code bottom} to {@code top}: walls and a flat roof. */
    public static Mesh prism(List<Point2> outline, float bottom, float top) {
        Builder mesh = new Builder();
        int n = outline.size();
        double orientation = Math.signum(Polygons.signedArea(outline));
        for (int i = 0; i < n; i++) {
            Point2 p = outline.get(i);
            Point2 q = outline.get((i + 1) % n);
            float dx = (float) (q.x() - p.x());
            float dz = (float) (q.z() - p.z());
            Vector3f outward = new Vector3f(dz, 0, -dx).multLocal((float) orientation).normalizeLocal();
            Vector3f a = new Vector3f((float) p.x(), bottom, (float) p.z());
            Vector3f b = new Vector3f((float) q.x(), bottom, (float) q.z());
            Vector3f c = new Vector3f((float) q.x(), top, (float) q.z());
            Vector3f d = new Vector3f((float) p.x(), top, (float) p.z());
            mesh.quad(a, b, c, d, outward);
        }
        addCap(mesh, outline, top, Vector3f.UNIT_Y);
        return mesh.build();
    }

    /** A flat polygon at height {@code y}, facing up. */
    public static Mesh polygon(List<Point2> outline, float y) {
        Builder mesh = new Builder();
        addCap(mesh, outline, y, Vector3f.UNIT_Y);
        return mesh.build();
    }

    /**
     * An upright cylinder from y = 0 to y = {@code height}, of radius {@code bottom} at its foot
     * and {@code top} at its head (0 makes a cone), closed at both ends.
     */
    public static Mesh cylinder(float bottom, float top, float height, int sides) {
        Builder mesh = new Builder();
        float slope = (bottom - top) / height;
        for (int i = 0; i < sides; i++) {
            float a0 = FastMath.TWO_PI * i / sides;
            float a1 = FastMath.TWO_PI * (i + 1) / sides;
            float mid = (a0 + a1) / 2;
            Vector3f normal = new Vector3f(FastMath.sin(mid), slope, FastMath.cos(mid)).normalizeLocal();
            Vector3f b0 = rim(a0, bottom, 0);
            Vector3f b1 = rim(a1, bottom, 0);
            Vector3f t0 = rim(a0, top, height);
            Vector3f t1 = rim(a1, top, height);
            mesh.triangle(b0, b1, t1, normal);
            if (top > 0) {
                mesh.triangle(b0, t1, t0, normal);
                mesh.triangle(new Vector3f(0, height, 0), t0, t1, Vector3f.UNIT_Y);
            }
            mesh.triangle(new Vector3f(0, 0, 0), b1, b0, Vector3f.UNIT_Y.negate());
        }
        return mesh.build();
    }

    /**
     * A flat sector on the ground around the origin, facing up: the part of a disc of
     * {@code radius} within {@code angle / 2} either side of the direction -z (north, where an
     * agent of heading 0 looks). An angle of 2π or more gives the whole disc.
     */
    public static Mesh sector(float radius, float angle, int segments) {
        Builder mesh = new Builder();
        float span = Math.min(angle, FastMath.TWO_PI);
        Vector3f centre = new Vector3f();
        for (int i = 0; i < segments; i++) {
            float a0 = -span / 2 + span * i / segments;
            float a1 = -span / 2 + span * (i + 1) / segments;
            mesh.triangle(centre, heading(a0, radius), heading(a1, radius), Vector3f.UNIT_Y);
        }
        return mesh.build();
    }

    /** The outline of {@link #sector} as lines: the arc, and the two edges unless it is a whole disc. */
    public static Mesh sectorOutline(float radius, float angle, int segments) {
        float span = Math.min(angle, FastMath.TWO_PI);
        boolean whole = span >= FastMath.TWO_PI - 1e-4f;
        List<Vector3f> points = new ArrayList<>();
        if (!whole) {
            points.add(new Vector3f());
        }
        for (int i = 0; i <= segments; i++) {
            points.add(heading(-span / 2 + span * i / segments, radius));
        }
        if (!whole) {
            points.add(new Vector3f());
        }
        return lineStrip(points);
    }

    /** A flat ring on the ground around the origin, facing up. */
    public static Mesh ring(float inner, float outer, int segments) {
        Builder mesh = new Builder();
        for (int i = 0; i < segments; i++) {
            float a0 = FastMath.TWO_PI * i / segments;
            float a1 = FastMath.TWO_PI * (i + 1) / segments;
            mesh.quad(heading(a0, inner), heading(a0, outer), heading(a1, outer), heading(a1, inner), Vector3f.UNIT_Y);
        }
        return mesh.build();
    }

    /**
     * A tube bent along an arc in the x/y plane, thickest in the middle and pointed at both
     * ends: a banana. The arc has radius {@code bend} and spans {@code angle}; it is centred on
     * the origin, curving upwards at its ends.
     */
    public static Mesh curvedTube(float bend, float angle, float thickness, int segments, int sides) {
        Builder mesh = new Builder();
        Vector3f[][] rings = new Vector3f[segments + 1][sides];
        Vector3f[] centres = new Vector3f[segments + 1];
        for (int i = 0; i <= segments; i++) {
            float t = (float) i / segments;
            float a = -angle / 2 + angle * t;
            Vector3f centre = new Vector3f(bend * FastMath.sin(a), bend * (1 - FastMath.cos(a)), 0);
            Vector3f along = new Vector3f(FastMath.cos(a), FastMath.sin(a), 0);
            Vector3f side = Vector3f.UNIT_Z;
            Vector3f up = side.cross(along);
            float r = thickness * Math.max(0.12f, FastMath.sin(FastMath.PI * t));
            centres[i] = centre;
            for (int k = 0; k < sides; k++) {
                float b = FastMath.TWO_PI * k / sides;
                rings[i][k] = centre.add(up.mult(r * FastMath.cos(b))).addLocal(side.mult(r * FastMath.sin(b)));
            }
        }
        for (int i = 0; i < segments; i++) {
            for (int k = 0; k < sides; k++) {
                int k1 = (k + 1) % sides;
                Vector3f a = rings[i][k];
                Vector3f b = rings[i + 1][k];
                Vector3f c = rings[i + 1][k1];
                Vector3f d = rings[i][k1];
                Vector3f mid = a.add(b).addLocal(c).addLocal(d).divideLocal(4);
                Vector3f axis = centres[i].add(centres[i + 1]).divideLocal(2);
                mesh.quad(a, b, c, d, mid.subtract(axis).normalizeLocal());
            }
        }
        return mesh.build();
    }

    /** A strip of lines through the points. */
    public static Mesh lineStrip(List<Vector3f> points) {
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.LineStrip);
        mesh.setBuffer(VertexBuffer.Type.Position, 3, BufferUtils.createFloatBuffer(points.toArray(new Vector3f[0])));
        mesh.updateBound();
        return mesh;
    }

    /** Separate lines, from {@code ends[0]} to {@code ends[1]}, {@code ends[2]} to {@code ends[3]} and so on. */
    public static Mesh lines(List<Vector3f> ends) {
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.Lines);
        mesh.setBuffer(VertexBuffer.Type.Position, 3, BufferUtils.createFloatBuffer(ends.toArray(new Vector3f[0])));
        mesh.updateBound();
        return mesh;
    }

    private static void addCap(Builder mesh, List<Point2> outline, float y, Vector3f normal) {
        int[] triangles = Polygons.triangulate(outline);
        for (int t = 0; t < triangles.length; t += 3) {
            mesh.triangle(at(outline.get(triangles[t]), y), at(outline.get(triangles[t + 1]), y),
                    at(outline.get(triangles[t + 2]), y), normal);
        }
    }

    private static Vector3f at(Point2 p, float y) {
        return new Vector3f((float) p.x(), y, (float) p.z());
    }

    private static Vector3f rim(float angle, float radius, float y) {
        return new Vector3f(radius * FastMath.sin(angle), y, radius * FastMath.cos(angle));
    }

    /** The point at {@code radius} in the direction of heading {@code angle} (0: -z, positive: towards -x). */
    private static Vector3f heading(float angle, float radius) {
        return new Vector3f(-radius * FastMath.sin(angle), 0, -radius * FastMath.cos(angle));
    }

    /** Collects flat-shaded triangles. */
    private static final class Builder {

        private final List<Vector3f> positions = new ArrayList<>();
        private final List<Vector3f> normals = new ArrayList<>();

        /** Adds a triangle, wound so that its front face looks along {@code facing}. */
        void triangle(Vector3f a, Vector3f b, Vector3f c, Vector3f facing) {
            Vector3f normal = b.subtract(a).crossLocal(c.subtract(a));
            if (normal.dot(facing) < 0) {
                Vector3f swap = b;
                b = c;
                c = swap;
            }
            Vector3f n = facing.normalize();
            positions.add(a);
            positions.add(b);
            positions.add(c);
            normals.add(n);
            normals.add(n);
            normals.add(n);
        }

        void quad(Vector3f a, Vector3f b, Vector3f c, Vector3f d, Vector3f facing) {
            triangle(a, b, c, facing);
            triangle(a, c, d, facing);
        }

        Mesh build() {
            Mesh mesh = new Mesh();
            mesh.setBuffer(VertexBuffer.Type.Position, 3,
                    BufferUtils.createFloatBuffer(positions.toArray(new Vector3f[0])));
            mesh.setBuffer(VertexBuffer.Type.Normal, 3, BufferUtils.createFloatBuffer(normals.toArray(new Vector3f[0])));
            int[] indices = new int[positions.size()];
            for (int i = 0; i < indices.length; i++) {
                indices[i] = i;
            }
            mesh.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createIntBuffer(indices));
            mesh.updateBound();
            mesh.updateCounts();
            return mesh;
        }
    }
}
