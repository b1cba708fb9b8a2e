package io.orchard.viewer.model.gltf;

import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * Gives the unnamed nodes and animation clips of a glTF document the names an agent can know
 * without loading the model: node {@code i} becomes {@code node#i} and clip {@code i} becomes
 * {@code clip#i}, by their indices in the file's {@code nodes} and {@code animations} arrays.
 * jME's loader would otherwise make up names of its own ({@code Joint_2}, {@code anim_0}) that
 * follow no rule an agent could rely on. Named ones keep their names.
 */
final class GltfNames {

    private static final int GLB_HEADER = 12;

    private GltfNames() {
    }

    /** The document with its unnamed nodes and clips named; the same bytes when all have names. */
    static byte[] named(ModelFormat format, byte[] bytes, ModelLimits limits) throws ModelException {
        int jsonLength = format == ModelFormat.GLB
                ? ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).getInt(GLB_HEADER) : bytes.length;
        int jsonStart = format == ModelFormat.GLB ? GLB_HEADER + 8 : 0;
        JsonNode root = GltfJson.read(new String(bytes, jsonStart, jsonLength, StandardCharsets.UTF_8), limits);
        boolean changed = name(root.get("nodes"), "node#") | name(root.get("animations"), "clip#");
        if (!changed) {
            return bytes;
        }
        byte[] json = root.toString().getBytes(StandardCharsets.UTF_8);
        if (format != ModelFormat.GLB) {
            return json;
        }
        // The JSON chunk is the first; the chunks after it are kept as they are.
        int padded = (json.length + 3) & ~3;
        int rest = bytes.length - (jsonStart + jsonLength);
        ByteBuffer glb = ByteBuffer.allocate(GLB_HEADER + 8 + padded + rest).order(ByteOrder.LITTLE_ENDIAN);
        glb.put(bytes, 0, 8).putInt(glb.capacity());
        glb.putInt(padded).putInt(ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).getInt(GLB_HEADER + 4));
        glb.put(json);
        for (int i = json.length; i < padded; i++) {
            glb.put((byte) ' ');
        }
        glb.put(bytes, jsonStart + jsonLength, rest);
        return glb.array();
    }

    private static boolean name(JsonNode array, String prefix) {
        boolean changed = false;
        if (array != null && array.isArray()) {
            for (int i = 0; i < array.size(); i++) {
                JsonNode name = array.get(i).get("name");
                if (array.get(i) instanceof ObjectNode entry
                        && (name == null || !name.isString() || name.stringValue().isEmpty())) {
                    entry.put("name", prefix + i);
                    changed = true;
                }
            }
        }
        return changed;
    }
}
