package io.orchard.viewer.model.build;

import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer.Type;
import com.jme3.util.BufferUtils;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.SceneNode;
import java.util.Arrays;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Turns IndexedFaceSet and IndexedLineSet nodes into jME meshes. Every corner of every face
 * becomes its own vertex, which is what per-face colours, per-face normals and sharp creases
 * need; faces are split into triangles as fans from their first corner, in the winding
 * {@code ccw} says. Normals that the file leaves out are computed: one per face, or smoothed
 * across faces that meet at less than {@code creaseAngle}.
 *
 * <p>Every index is checked against the array it points into; an index outside it is a
 * {@link ModelException} naming the field, the position and the value.
 */
final class FaceSets {

    private static final Logger LOG = LoggerFactory.getLogger(FaceSets.class);

    /** A built mesh and what its material must know. */
    record Built(Mesh mesh, boolean vertexColors, boolean lines, boolean solid) {
    }

    private FaceSets() {
    }

    /** The mesh of an IndexedFaceSet, or null when it has no coordinates or no whole face. */
    static Built faceSet(SceneNode node, boolean generateTexCoords) throws ModelException {
        float[] points = points(node);
        int[] coordIndex = node.ints("coordIndex");
        int pointCount = points.length / 3;
        Faces faces = Faces.split(node, coordIndex, pointCount);
        if (faces.count == 0) {
            LOG.warn("{} has no face with three or more corners; it is not drawn", node.label());
            return null;
        }
        if (!node.bool("convex")) {
            LOG.debug("{}: non-convex faces are split as fans and may show artefacts",
                    node.label());
        }
        boolean ccw = node.bool("ccw");
        int corners = faces.corners;
        float[] positions = new float[corners * 3];
        for (int k = 0; k < corners; k++) {
            System.arraycopy(points, 3 * coordIndex[faces.cornerPosition[k]], positions, 3 * k, 3);
        }
        Mesh mesh = new Mesh();
        mesh.setBuffer(Type.Position, 3, BufferUtils.createFloatBuffer(positions));
        mesh.setBuffer(Type.Normal, 3, BufferUtils.createFloatBuffer(
                normals(node, faces, coordIndex, points, ccw)));
        float[] colors = colors(node, faces, "colorIndex", "colorPerVertex", coordIndex);
        if (colors != null) {
            mesh.setBuffer(Type.Color, 4, BufferUtils.createFloatBuffer(colors));
        }
        float[] texCoords = texCoords(node, faces, coordIndex, points, generateTexCoords);
        if (texCoords != null) {
            mesh.setBuffer(Type.TexCoord, 2, BufferUtils.createFloatBuffer(texCoords));
        }
        int[] indices = new int[faces.triangles() * 3];
        int n = 0;
        for (int f = 0; f < faces.count; f++) {
            int base = faces.firstCorner[f];
            for (int i = 1; i < faces.size[f] - 1; i++) {
                indices[n++] = base;
                indices[n++] = base + (ccw ? i : i + 1);
                indices[n++] = base + (ccw ? i + 1 : i);
            }
        }
        mesh.setBuffer(Type.Index, 3, BufferUtils.createIntBuffer(indices));
        mesh.updateBound();
        mesh.updateCounts();
        return new Built(mesh, colors != null, false, node.bool("solid"));
    }

    /** The mesh of an IndexedLineSet, or null when it has no segment. */
    static Built lineSet(SceneNode node) throws ModelException {
        float[] points = points(node);
        int[] coordIndex = node.ints("coordIndex");
        Faces lines = Faces.split(node, coordIndex, points.length / 3, 2);
        if (lines.count == 0) {
            LOG.warn("{} has no line with two or more points; it is not drawn", node.label());
            return null;
        }
        float[] positions = new float[lines.corners * 3];
        for (int k = 0; k < lines.corners; k++) {
            System.arraycopy(points, 3 * coordIndex[lines.cornerPosition[k]], positions, 3 * k, 3);
        }
        int segments = lines.corners - lines.count;
        int[] indices = new int[segments * 2];
        int n = 0;
        for (int f = 0; f < lines.count; f++) {
            for (int i = 0; i < lines.size[f] - 1; i++) {
                indices[n++] = lines.firstCorner[f] + i;
                indices[n++] = lines.firstCorner[f] + i + 1;
            }
        }
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.Lines);
        mesh.setBuffer(Type.Position, 3, BufferUtils.createFloatBuffer(positions));
        float[] colors = colors(node, lines, "colorIndex", "colorPerVertex", coordIndex);
        if (colors != null) {
            mesh.setBuffer(Type.Color, 4, BufferUtils.createFloatBuffer(colors));
        }
        mesh.setBuffer(Type.Index, 2, BufferUtils.createIntBuffer(indices));
        mesh.updateBound();
        mesh.updateCounts();
        return new Built(mesh, colors != null, true, false);
    }

    private static float[] points(SceneNode node) {
        SceneNode coord = node.node("coord", "Coordinate");
        return coord == null ? new float[0] : coord.floats("point");
    }

    private static float[] normals(SceneNode node, Faces faces, int[] coordIndex, float[] points,
                                   boolean ccw) throws ModelException {
        SceneNode normal = node.node("normal", "Normal");
        if (normal != null) {
            float[] vectors = normal.floats("vector");
            return perCorner(node, faces, vectors, 3, "normalIndex", node.bool("normalPerVertex"),
                    coordIndex, normal.label() + " field vector");
        }
        float[] faceNormals = new float[faces.count * 3];
        for (int f = 0; f < faces.count; f++) {
            FaceNormals.newell(faces, f, coordIndex, points, ccw, faceNormals);
        }
        float[] result = new float[faces.corners * 3];
        double crease = node.number("creaseAngle");
        if (crease <= 0) {
            for (int f = 0; f < faces.count; f++) {
                for (int i = 0; i < faces.size[f]; i++) {
                    System.arraycopy(faceNormals, 3 * f, result, 3 * (faces.firstCorner[f] + i), 3);
                }
            }
            return result;
        }
        FaceNormals.smooth(faces, coordIndex, points.length / 3, faceNormals, Math.cos(crease), result);
        return result;
    }

    /** RGBA per corner from the Color node, or null when there is none. */
    private static float[] colors(SceneNode node, Faces faces, String indexField,
                                  String perVertexField, int[] coordIndex) throws ModelException {
        SceneNode color = node.node("color", "Color");
        if (color == null) {
            return null;
        }
        float[] rgb = perCorner(node, faces, color.floats("color"), 3, indexField,
                node.bool(perVertexField), coordIndex, color.label() + " field color");
        float[] rgba = new float[faces.corners * 4];
        for (int k = 0; k < faces.corners; k++) {
            rgba[4 * k] = rgb[3 * k];
            rgba[4 * k + 1] = rgb[3 * k + 1];
            rgba[4 * k + 2] = rgb[3 * k + 2];
            rgba[4 * k + 3] = 1f;
        }
        return rgba;
    }

    private static float[] texCoords(SceneNode node, Faces faces, int[] coordIndex,
                                     float[] points, boolean generate) throws ModelException {
        SceneNode texCoord = node.node("texCoord", "TextureCoordinate");
        if (texCoord != null) {
            return perCorner(node, faces, texCoord.floats("point"), 2, "texCoordIndex", true,
                    coordIndex, texCoord.label() + " field point");
        }
        return generate ? boxMapping(faces, coordIndex, points) : null;
    }

    /**
     * Spreads {@code values} (of {@code width} numbers each) over the corners: per vertex through
     * {@code indexField} (or coordIndex when it is empty), or per face through
     * {@code indexField} (or in face order when it is empty).
     */
    private static float[] perCorner(SceneNode node, Faces faces, float[] values, int width,
                                     String indexField, boolean perVertex, int[] coordIndex,
                                     String valuesName) throws ModelException {
        int available = values.length / width;
        int[] index = node.ints(indexField);
        float[] result = new float[faces.corners * width];
        for (int f = 0; f < faces.count; f++) {
            for (int i = 0; i < faces.size[f]; i++) {
                int corner = faces.firstCorner[f] + i;
                int position;
                int value;
                String source;
                if (perVertex) {
                    position = faces.cornerPosition[corner];
                    boolean own = index.length > 0;
                    source = own ? indexField : "coordIndex";
                    if (own && position >= index.length) {
                        throw new ModelException(Kind.BAD_VALUE, node.location() + ": "
                                + node.label() + " field " + indexField + " has "
                                + index.length + " entries but coordIndex needs one at position "
                                + position);
                    }
                    value = own ? index[position] : coordIndex[position];
                } else {
                    position = faces.faceNumber[f];
                    boolean own = index.length > 0;
                    source = own ? indexField : "face order";
                    if (own && position >= index.length) {
                        throw new ModelException(Kind.BAD_VALUE, node.location() + ": "
                                + node.label() + " field " + indexField + " has "
                                + index.length + " entries but there are more faces (face "
                                + position + ")");
                    }
                    value = own ? index[position] : position;
                }
                if (value < 0 || value >= available) {
                    throw new ModelException(Kind.BAD_VALUE, node.location() + ": "
                            + node.label() + " field " + source + ": value " + value
                            + " at position " + position + " is outside the " + available
                            + " entries of " + valuesName);
                }
                System.arraycopy(values, width * value, result, width * corner, width);
            }
        }
        return result;
    }

    /** VRML's default texture mapping: the longest box side is s, the second longest t. */
    private static float[] boxMapping(Faces faces, int[] coordIndex, float[] points) {
        float[] min = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE};
        float[] max = {-Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        for (int k = 0; k < faces.corners; k++) {
            int p = 3 * coordIndex[faces.cornerPosition[k]];
            for (int a = 0; a < 3; a++) {
                min[a] = Math.min(min[a], points[p + a]);
                max[a] = Math.max(max[a], points[p + a]);
            }
        }
        Integer[] axes = {0, 1, 2};
        Arrays.sort(axes, (a, b) -> Float.compare(max[b] - min[b], max[a] - min[a]));
        int s = axes[0];
        int t = axes[1];
        float size = max[s] - min[s];
        float scale = size > 0 ? 1f / size : 0f;
        float[] result = new float[faces.corners * 2];
        for (int k = 0; k < faces.corners; k++) {
            int p = 3 * coordIndex[faces.cornerPosition[k]];
            result[2 * k] = (points[p + s] - min[s]) * scale;
            result[2 * k + 1] = (points[p + t] - min[t]) * scale;
        }
        return result;
    }

    /**
     * The faces (or polylines) of a coordIndex: for each, its first corner, its size and its
     * number among all faces written (short ones included, for per-face colour indices); for
     * each corner, its position in coordIndex.
     */
    static final class Faces {

        int count;
        int corners;
        int[] firstCorner;
        int[] size;
        int[] faceNumber;
        int[] cornerPosition;

        static Faces split(SceneNode node, int[] coordIndex, int pointCount)
                throws ModelException {
            return split(node, coordIndex, pointCount, 3);
        }

        static Faces split(SceneNode node, int[] coordIndex, int pointCount, int minimum)
                throws ModelException {
            Faces faces = new Faces();
            faces.firstCorner = new int[16];
            faces.size = new int[16];
            faces.faceNumber = new int[16];
            faces.cornerPosition = new int[coordIndex.length];
            int written = 0;
            int start = 0;
            for (int i = 0; i <= coordIndex.length; i++) {
                boolean end = i == coordIndex.length || coordIndex[i] == -1;
                if (!end) {
                    int value = coordIndex[i];
                    if (value < 0 || value >= pointCount) {
                        throw new ModelException(Kind.BAD_VALUE, node.location() + ": "
                                + node.label() + " field coordIndex: value " + value
                                + " at position " + i + " is outside the " + pointCount
                                + " points of its Coordinate");
                    }
                    continue;
                }
                int length = i - start;
                if (length > 0) {
                    if (length >= minimum) {
                        faces.add(start, length, written);
                    }
                    written++;
                }
                start = i + 1;
            }
            return faces;
        }

        private void add(int start, int length, int number) {
            if (count == firstCorner.length) {
                firstCorner = Arrays.copyOf(firstCorner, count * 2);
                size = Arrays.copyOf(size, count * 2);
                faceNumber = Arrays.copyOf(faceNumber, count * 2);
            }
            firstCorner[count] = corners;
            size[count] = length;
            faceNumber[count] = number;
            for (int i = 0; i < length; i++) {
                cornerPosition[corners + i] = start + i;
            }
            corners += length;
            count++;
        }

        int triangles() {
            int total = 0;
            for (int f = 0; f < count; f++) {
                total += size[f] - 2;
            }
            return total;
        }
    }
}
