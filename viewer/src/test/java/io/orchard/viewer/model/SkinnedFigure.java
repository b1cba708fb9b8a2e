package io.orchard.viewer.model;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;

/**
 * A glTF figure written for the tests with the features real exports have: a skinned body (a
 * box from the feet to 1.6 m, its lower half bound to the joint {@code Hips root.L}, its upper
 * half to an unnamed joint 0.8 m up), a node {@code Flag} (a box above the right shoulder), a
 * clip {@code Wave.Arm} that bends the upper body 90 degrees to the left and back over one
 * second, and an unnamed clip that raises the flag by 0.8 m and back. The JSON is written here
 * and the buffer generated, so the figure is source, not a file taken from elsewhere.
 */
public final class SkinnedFigure {

    /** The named joint at the hips. */
    public static final String HIPS = "Hips root.L";
    /** The named clip that bends the upper body. */
    public static final String WAVE = "Wave.Arm";

    private final ByteArrayOutputStream bin = new ByteArrayOutputStream();
    private final List<String> views = new ArrayList<>();
    private final List<String> accessors = new ArrayList<>();

    private SkinnedFigure() {
    }

    /** The figure as one .gltf file with its buffer embedded as a data: URI. */
    public static byte[] embedded() {
        return embedded("");
    }

    /**
     * The figure as one .gltf file, its node {@code Figure} given {@code transform}: JSON members
     * such as {@code "scale": [100, 100, 100], } for a figure authored in centimetres.
     */
    public static byte[] embedded(String transform) {
        SkinnedFigure figure = new SkinnedFigure();
        byte[] buffer = figure.buffer();
        String uri = "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(buffer);
        return figure.json("\"uri\": \"" + uri + "\", ", buffer.length)
                .replace("{\"name\": \"Figure\", ", "{\"name\": \"Figure\", " + transform)
                .getBytes(StandardCharsets.UTF_8);
    }

    /** The figure as binary glTF: the buffer in the BIN chunk. */
    public static byte[] glb() {
        SkinnedFigure figure = new SkinnedFigure();
        byte[] buffer = figure.buffer();
        byte[] text = figure.json("", buffer.length).getBytes(StandardCharsets.UTF_8);
        int textLength = (text.length + 3) & ~3;
        ByteBuffer glb = ByteBuffer.allocate(12 + 8 + textLength + 8 + buffer.length).order(ByteOrder.LITTLE_ENDIAN);
        glb.putInt(0x46546C67).putInt(2).putInt(glb.capacity());
        glb.putInt(textLength).putInt(0x4E4F534A).put(text);
        for (int i = text.length; i < textLength; i++) {
            glb.put((byte) ' ');
        }
        glb.putInt(buffer.length).putInt(0x004E4942).put(buffer);
        return glb.array();
    }

    /** The figure's JSON referring to its buffer as the external file {@code uri}. */
    public static String withExternalBuffer(String uri) {
        SkinnedFigure figure = new SkinnedFigure();
        byte[] buffer = figure.buffer();
        return figure.json("\"uri\": \"" + uri + "\", ", buffer.length);
    }

    /** The buffer an external .bin holds. */
    public static byte[] bufferBytes() {
        return new SkinnedFigure().buffer();
    }

    private byte[] buffer() {
        if (bin.size() > 0) {
            return bin.toByteArray();
        }
        // Body: two boxes, 8 corners each; lower bound to joint 0, upper to joint 1.
        float[] positions = new float[16 * 3];
        int[] joints = new int[16 * 4];
        float[] weights = new float[16 * 4];
        for (int box = 0; box < 2; box++) {
            float bottom = box * 0.8f;
            for (int corner = 0; corner < 8; corner++) {
                int v = box * 8 + corner;
                positions[v * 3] = (corner & 1) == 0 ? -0.25f : 0.25f;
                positions[v * 3 + 1] = (corner & 2) == 0 ? bottom : bottom + 0.8f;
                positions[v * 3 + 2] = (corner & 4) == 0 ? -0.15f : 0.15f;
                joints[v * 4] = box;
                weights[v * 4] = 1;
            }
        }
        short[] indices = new short[2 * 36];
        int[][] faces = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
        int i = 0;
        for (int box = 0; box < 2; box++) {
            for (int[] f : faces) {
                int[] tri = {f[0], f[2], f[1], f[0], f[3], f[2]};
                for (int corner : tri) {
                    indices[i++] = (short) (box * 8 + corner);
                }
            }
        }
        view(floats(positions), 16, "VEC3", 5126, ", \"min\": [-0.25, 0, -0.15], \"max\": [0.25, 1.6, 0.15]");
        view(bytes(joints), 16, "VEC4", 5121, "");
        view(floats(weights), 16, "VEC4", 5126, "");
        view(shorts(indices), indices.length, "SCALAR", 5123, "");
        float[] inverseBinds = new float[32];
        for (int m = 0; m < 2; m++) {
            inverseBinds[m * 16] = 1;
            inverseBinds[m * 16 + 5] = 1;
            inverseBinds[m * 16 + 10] = 1;
            inverseBinds[m * 16 + 15] = 1;
        }
        inverseBinds[16 + 13] = -0.8f;
        view(floats(inverseBinds), 2, "MAT4", 5126, "");
        // Flag: one box of 0.3 m, its faces those of the body's lower box.
        float[] flag = new float[8 * 3];
        for (int corner = 0; corner < 8; corner++) {
            flag[corner * 3] = (corner & 1) == 0 ? -0.15f : 0.15f;
            flag[corner * 3 + 1] = (corner & 2) == 0 ? -0.15f : 0.15f;
            flag[corner * 3 + 2] = (corner & 4) == 0 ? -0.15f : 0.15f;
        }
        view(floats(flag), 8, "VEC3", 5126, ", \"min\": [-0.15, -0.15, -0.15], \"max\": [0.15, 0.15, 0.15]");
        short[] flagIndices = new short[36];
        System.arraycopy(indices, 0, flagIndices, 0, 36);
        view(shorts(flagIndices), 36, "SCALAR", 5123, "");
        view(floats(new float[] {0, 0.5f, 1}), 3, "SCALAR", 5126, ", \"min\": [0], \"max\": [1]");
        float bend = (float) Math.sin(Math.PI / 4);
        view(floats(new float[] {0, 0, 0, 1, 0, 0, bend, bend, 0, 0, 0, 1}), 3, "VEC4", 5126, "");
        view(floats(new float[] {0.6f, 1.2f, 0, 0.6f, 2.0f, 0, 0.6f, 1.2f, 0}), 3, "VEC3", 5126, "");
        return bin.toByteArray();
    }

    private String json(String bufferUri, int length) {
        return """
                {
                  "asset": {"version": "2.0", "generator": "Orchard's tests, by hand"},
                  "scene": 0,
                  "scenes": [{"nodes": [0]}],
                  "nodes": [
                    {"name": "Figure", "children": [1, 3, 4]},
                    {"name": "%s", "children": [2]},
                    {"translation": [0, 0.8, 0]},
                    {"name": "Body", "mesh": 0, "skin": 0},
                    {"name": "Flag", "mesh": 1, "translation": [0.6, 1.2, 0]}
                  ],
                  "skins": [{"joints": [1, 2], "inverseBindMatrices": 4, "skeleton": 1}],
                  "materials": [
                    {"pbrMetallicRoughness": {"baseColorFactor": [1, 0.45, 0, 1], "metallicFactor": 0}},
                    {"pbrMetallicRoughness": {"baseColorFactor": [0, 0.8, 1, 1], "metallicFactor": 0}}
                  ],
                  "meshes": [
                    {"primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 1, "WEIGHTS_0": 2}, "indices": 3,
                                     "material": 0}]},
                    {"primitives": [{"attributes": {"POSITION": 5}, "indices": 6, "material": 1}]}
                  ],
                  "animations": [
                    {"name": "%s",
                     "samplers": [{"input": 7, "output": 8, "interpolation": "LINEAR"}],
                     "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]},
                    {"samplers": [{"input": 7, "output": 9, "interpolation": "LINEAR"}],
                     "channels": [{"sampler": 0, "target": {"node": 4, "path": "translation"}}]}
                  ],
                  "buffers": [{%s"byteLength": %d}],
                  "bufferViews": [%s],
                  "accessors": [%s]
                }
                """.formatted(HIPS, WAVE, bufferUri, length, String.join(",\n    ", views),
                String.join(",\n    ", accessors));
    }

    private void view(byte[] data, int count, String type, int componentType, String extra) {
        int offset = bin.size();
        bin.writeBytes(data);
        while (bin.size() % 4 != 0) {
            bin.write(0);
        }
        int index = views.size();
        views.add("{\"buffer\": 0, \"byteOffset\": " + offset + ", \"byteLength\": " + data.length + "}");
        accessors.add("{\"bufferView\": " + index + ", \"componentType\": " + componentType + ", \"count\": " + count
                + ", \"type\": \"" + type + "\"" + extra + "}");
    }

    private static byte[] floats(float[] values) {
        ByteBuffer out = ByteBuffer.allocate(values.length * 4).order(ByteOrder.LITTLE_ENDIAN);
        for (float v : values) {
            out.putFloat(v);
        }
        return out.array();
    }

    private static byte[] shorts(short[] values) {
        ByteBuffer out = ByteBuffer.allocate(values.length * 2).order(ByteOrder.LITTLE_ENDIAN);
        for (short v : values) {
            out.putShort(v);
        }
        return out.array();
    }

    private static byte[] bytes(int[] values) {
        byte[] out = new byte[values.length];
        for (int i = 0; i < values.length; i++) {
            out[i] = (byte) values[i];
        }
        return out;
    }
}
