package io.orchard.viewer.model;

import io.orchard.protocol.value.ModelArchive;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;

/**
 * A glTF written for the tests as modelling tools export one: a textured block in centimetres
 * (50 wide, 200 tall, 30 deep) with its origin off its centre and off the ground (the block runs
 * from x 100 to 150, y 20 to 220, z -40 to -10), in a folder {@code Block/} with its buffer
 * {@code block.bin} and its magenta texture {@code textures/block skin.png} as files of their own,
 * zipped. Fitted to a body 1.6 m tall the block is 0.4 m wide, stands from 0 to 1.6 m and is
 * centred on the agent. The JSON is written here and the buffer and image generated.
 */
public final class SplitBlock {

    /** The node that moves: the agent's name. */
    public static final String NAME = "Block";

    private static final float[][] FACES = {
        // normal, then the two axes that span the face
        {1, 0, 0, 0, 1, 0, 0, 0, 1}, {-1, 0, 0, 0, 1, 0, 0, 0, 1},
        {0, 1, 0, 1, 0, 0, 0, 0, 1}, {0, -1, 0, 1, 0, 0, 0, 0, 1},
        {0, 0, 1, 1, 0, 0, 0, 1, 0}, {0, 0, -1, 1, 0, 0, 0, 1, 0},
    };
    private static final float[] MIN = {100, 20, -40};
    private static final float[] MAX = {150, 220, -10};

    private SplitBlock() {
    }

    /** The zip: {@code Block/block.gltf}, {@code Block/block.bin}, {@code Block/textures/block skin.png}. */
    public static byte[] zip() {
        Map<String, byte[]> files = new LinkedHashMap<>();
        byte[] bin = buffer();
        files.put("Block/block.gltf", json(bin.length).getBytes(StandardCharsets.UTF_8));
        files.put("Block/block.bin", bin);
        files.put("Block/textures/block skin.png", magenta());
        return ModelArchive.pack(files);
    }

    private static byte[] buffer() {
        ByteBuffer out = ByteBuffer.allocate(24 * 12 + 24 * 8 + 24 * 12 + 36 * 2).order(ByteOrder.LITTLE_ENDIAN);
        float[] centre = new float[3];
        float[] half = new float[3];
        for (int a = 0; a < 3; a++) {
            centre[a] = (MIN[a] + MAX[a]) / 2;
            half[a] = (MAX[a] - MIN[a]) / 2;
        }
        float[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (float[] face : FACES) {
            for (float[] corner : corners) {
                for (int a = 0; a < 3; a++) {
                    out.putFloat(centre[a] + (face[a] + face[3 + a] * corner[0] + face[6 + a] * corner[1]) * half[a]);
                }
            }
        }
        for (int i = 0; i < 6; i++) {
            for (float[] corner : corners) {
                out.putFloat((corner[0] + 1) / 2).putFloat((corner[1] + 1) / 2);
            }
        }
        for (float[] face : FACES) {
            for (int k = 0; k < 4; k++) {
                out.putFloat(face[0]).putFloat(face[1]).putFloat(face[2]);
            }
        }
        for (int f = 0; f < 6; f++) {
            int b = f * 4;
            out.putShort((short) b).putShort((short) (b + 1)).putShort((short) (b + 2));
            out.putShort((short) b).putShort((short) (b + 2)).putShort((short) (b + 3));
        }
        return out.array();
    }

    private static String json(int length) {
        int positions = 24 * 12;
        int uvs = 24 * 8;
        int normals = 24 * 12;
        return String.format(Locale.ROOT, """
                {"asset": {"version": "2.0", "generator": "Orchard tests"},
                 "scene": 0, "scenes": [{"nodes": [0]}],
                 "nodes": [{"name": "Block", "mesh": 0}],
                 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "NORMAL": 2},
                   "indices": 3, "material": 0}]}],
                 "materials": [{"doubleSided": true, "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                   "metallicFactor": 0.0}}],
                 "textures": [{"source": 0}],
                 "images": [{"uri": "textures/block%%20skin.png"}],
                 "buffers": [{"uri": "block.bin", "byteLength": %d}],
                 "bufferViews": [
                   {"buffer": 0, "byteOffset": 0, "byteLength": %d},
                   {"buffer": 0, "byteOffset": %d, "byteLength": %d},
                   {"buffer": 0, "byteOffset": %d, "byteLength": %d},
                   {"buffer": 0, "byteOffset": %d, "byteLength": 72}],
                 "accessors": [
                   {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3",
                    "min": [100, 20, -40], "max": [150, 220, -10]},
                   {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC2"},
                   {"bufferView": 2, "componentType": 5126, "count": 24, "type": "VEC3"},
                   {"bufferView": 3, "componentType": 5123, "count": 36, "type": "SCALAR"}]}
                """, length, positions, positions, uvs, positions + uvs, normals, positions + uvs + normals);
    }

    private static byte[] magenta() {
        BufferedImage image = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < 4; x++) {
            for (int y = 0; y < 4; y++) {
                image.setRGB(x, y, 0xFF00FF);
            }
        }
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", png);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return png.toByteArray();
    }
}
