package io.orchard.viewer.model.build;

import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer.Type;
import com.jme3.scene.shape.Box;
import com.jme3.util.BufferUtils;

/**
 * Meshes for VRML's four primitives with VRML's conventions: centred on the origin, the axis of
 * cylinders and cones along +Y, the apex of a cone up, texture seams at the back (-Z), and
 * optional parts (a cylinder's top, side, bottom) left out when their field is FALSE. jME's own
 * shapes put their axis along Z, hence these.
 */
final class Primitives {

    /** Segments around the Y axis. */
    static final int SLICES = 32;
    /** Bands from pole to pole on a sphere. */
    static final int STACKS = 16;

    private Primitives() {
    }

    /** A box of the given full size (VRML's {@code size}; jME's Box takes half extents). */
    static Mesh box(float sizeX, float sizeY, float sizeZ) {
        return new Box(sizeX / 2, sizeY / 2, sizeZ / 2);
    }

    static Mesh sphere(float radius) {
        MeshData data = new MeshData((STACKS + 1) * (SLICES + 1), (STACKS - 1) * SLICES * 6);
        for (int i = 0; i <= STACKS; i++) {
            double latitude = Math.PI * i / STACKS - Math.PI / 2;
            float y = (float) Math.sin(latitude);
            float ring = (float) Math.cos(latitude);
            for (int j = 0; j <= SLICES; j++) {
                double angle = 2 * Math.PI * j / SLICES;
                float x = (float) -Math.sin(angle) * ring;
                float z = (float) -Math.cos(angle) * ring;
                data.vertex(x * radius, y * radius, z * radius, x, y, z,
                        (float) j / SLICES, (float) i / STACKS);
            }
        }
        for (int i = 0; i < STACKS; i++) {
            for (int j = 0; j < SLICES; j++) {
                int a = i * (SLICES + 1) + j;
                // At the poles one of the quad's triangles has no area: leave it out.
                if (i > 0) {
                    data.triangle(a, a + 1, a + SLICES + 2);
                }
                if (i < STACKS - 1) {
                    data.triangle(a, a + SLICES + 2, a + SLICES + 1);
                }
            }
        }
        return data.toMesh();
    }

    static Mesh cylinder(float radius, float height, boolean side, boolean top, boolean bottom) {
        int vertices = (side ? 2 * (SLICES + 1) : 0) + (top ? SLICES + 2 : 0)
                + (bottom ? SLICES + 2 : 0);
        int indices = (side ? SLICES * 6 : 0) + (top ? SLICES * 3 : 0)
                + (bottom ? SLICES * 3 : 0);
        MeshData data = new MeshData(vertices, indices);
        float half = height / 2;
        if (side) {
            int first = data.vertexCount();
            for (int row = 0; row <= 1; row++) {
                for (int j = 0; j <= SLICES; j++) {
                    double angle = 2 * Math.PI * j / SLICES;
                    float x = (float) -Math.sin(angle);
                    float z = (float) -Math.cos(angle);
                    data.vertex(x * radius, row == 0 ? -half : half, z * radius, x, 0, z,
                            (float) j / SLICES, row);
                }
            }
            for (int j = 0; j < SLICES; j++) {
                int a = first + j;
                data.quad(a, a + 1, a + SLICES + 2, a + SLICES + 1);
            }
        }
        if (top) {
            cap(data, radius, half, true);
        }
        if (bottom) {
            cap(data, radius, -half, false);
        }
        return data.toMesh();
    }

    static Mesh cone(float bottomRadius, float height, boolean side, boolean bottom) {
        int vertices = (side ? 2 * (SLICES + 1) : 0) + (bottom ? SLICES + 2 : 0);
        int indices = (side ? SLICES * 3 : 0) + (bottom ? SLICES * 3 : 0);
        MeshData data = new MeshData(vertices, indices);
        float half = height / 2;
        if (side) {
            double slope = Math.hypot(height, bottomRadius);
            float ny = (float) (bottomRadius / slope);
            float nr = (float) (height / slope);
            int first = data.vertexCount();
            for (int j = 0; j <= SLICES; j++) {
                double angle = 2 * Math.PI * j / SLICES;
                float x = (float) -Math.sin(angle);
                float z = (float) -Math.cos(angle);
                data.vertex(x * bottomRadius, -half, z * bottomRadius, x * nr, ny, z * nr,
                        (float) j / SLICES, 0);
            }
            for (int j = 0; j <= SLICES; j++) {
                double angle = 2 * Math.PI * (j + 0.5) / SLICES;
                float x = (float) -Math.sin(angle);
                float z = (float) -Math.cos(angle);
                data.vertex(0, half, 0, x * nr, ny, z * nr, (j + 0.5f) / SLICES, 1);
            }
            for (int j = 0; j < SLICES; j++) {
                data.triangle(first + j, first + j + 1, first + SLICES + 1 + j);
            }
        }
        if (bottom) {
            cap(data, bottomRadius, -half, false);
        }
        return data.toMesh();
    }

    /** A disc at height {@code y}, facing up or down. */
    private static void cap(MeshData data, float radius, float y, boolean up) {
        float ny = up ? 1 : -1;
        int centre = data.vertexCount();
        data.vertex(0, y, 0, 0, ny, 0, 0.5f, 0.5f);
        for (int j = 0; j <= SLICES; j++) {
            double angle = 2 * Math.PI * j / SLICES;
            float x = (float) -Math.sin(angle);
            float z = (float) -Math.cos(angle);
            data.vertex(x * radius, y, z * radius, 0, ny, 0, 0.5f + x / 2,
                    up ? 0.5f - z / 2 : 0.5f + z / 2);
        }
        for (int j = 0; j < SLICES; j++) {
            if (up) {
                data.triangle(centre, centre + 1 + j, centre + 2 + j);
            } else {
                data.triangle(centre, centre + 2 + j, centre + 1 + j);
            }
        }
    }

    /** Vertex and index arrays filled in order, then turned into a mesh. */
    private static final class MeshData {

        private final float[] positions;
        private final float[] normals;
        private final float[] texCoords;
        private final int[] indices;
        private int vertices;
        private int indexCount;

        MeshData(int vertexCapacity, int indexCapacity) {
            positions = new float[vertexCapacity * 3];
            normals = new float[vertexCapacity * 3];
            texCoords = new float[vertexCapacity * 2];
            indices = new int[indexCapacity];
        }

        int vertexCount() {
            return vertices;
        }

        void vertex(float x, float y, float z, float nx, float ny, float nz, float s, float t) {
            positions[3 * vertices] = x;
            positions[3 * vertices + 1] = y;
            positions[3 * vertices + 2] = z;
            normals[3 * vertices] = nx;
            normals[3 * vertices + 1] = ny;
            normals[3 * vertices + 2] = nz;
            texCoords[2 * vertices] = s;
            texCoords[2 * vertices + 1] = t;
            vertices++;
        }

        void triangle(int a, int b, int c) {
            indices[indexCount++] = a;
            indices[indexCount++] = b;
            indices[indexCount++] = c;
        }

        /** Two triangles; corners counter-clockwise as seen from the front. */
        void quad(int a, int b, int c, int d) {
            triangle(a, b, c);
            triangle(a, c, d);
        }

        Mesh toMesh() {
            Mesh mesh = new Mesh();
            mesh.setBuffer(Type.Position, 3, BufferUtils.createFloatBuffer(positions));
            mesh.setBuffer(Type.Normal, 3, BufferUtils.createFloatBuffer(normals));
            mesh.setBuffer(Type.TexCoord, 2, BufferUtils.createFloatBuffer(texCoords));
            mesh.setBuffer(Type.Index, 3, BufferUtils.createIntBuffer(indices));
            mesh.updateBound();
            mesh.updateCounts();
            return mesh;
        }
    }
}
