package io.orchard.viewer.model.gltf;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelFiles;
import io.orchard.viewer.model.ModelLimits;
import java.nio.charset.StandardCharsets;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * Makes a glTF of a zip self-contained: each buffer and image {@code uri} that names a file of the
 * archive becomes a {@code data:} URI carrying it, so that jME's loader, which would otherwise look
 * the files up through the asset manager, reads nothing but these bytes. A URI that leaves the
 * archive is refused by {@link ModelFiles}.
 */
final class GltfEmbedding {

    private GltfEmbedding() {
    }

    /** The glTF JSON with its files embedded; the same bytes when it refers to none. */
    static byte[] embedded(byte[] gltf, ModelFiles files, ModelLimits limits) throws ModelException {
        if (!files.any()) {
            return gltf;
        }
        JsonNode root = GltfJson.read(new String(gltf, StandardCharsets.UTF_8), limits);
        boolean changed = false;
        for (String array : new String[] {"buffers", "images"}) {
            JsonNode entries = root.get(array);
            if (entries == null || !entries.isArray()) {
                continue;
            }
            for (int i = 0; i < entries.size(); i++) {
                JsonNode uri = entries.get(i).get("uri");
                if (uri != null && uri.isString() && entries.get(i) instanceof ObjectNode entry) {
                    String embedded = files.embedded(uri.stringValue(), files.path() + " " + array
                            + "[" + i + "].uri");
                    changed |= !embedded.equals(uri.stringValue());
                    entry.put("uri", embedded);
                }
            }
        }
        return changed ? root.toString().getBytes(StandardCharsets.UTF_8) : gltf;
    }
}
