package io.orchard.agents;

import io.orchard.protocol.StrictJson;
import io.orchard.protocol.value.ModelSpec;
import java.io.IOException;
import java.io.InputStream;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Base64;
import java.util.Deque;
import java.util.Locale;
import java.util.Map;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ObjectNode;

/**
 * Packs a glTF file exported the usual way, its buffers ({@code .bin}) and textures in files next
 * to it, into one self-contained .gltf whose every URI is an embedded {@code data:} URI: the one
 * file the protocol's {@code ModelSpec} carries and viewers accept. A URI is resolved relative
 * to the model's own folder among the agent's resources and must stay within it: no scheme (so
 * never the network), no absolute path, no {@code ..} that leaves the folder.
 */
final class GltfPacking {

    private static final JsonMapper JSON = StrictJson.builder().build();
    private static final Map<String, String> MEDIA_TYPES = Map.of("png", "image/png", "jpg", "image/jpeg",
            "jpeg", "image/jpeg", "bin", "application/octet-stream");

    private GltfPacking() {
    }

    /**
     * The model with its external files embedded; the same bytes when it refers to none.
     *
     * @param owner    the class whose resources hold the model
     * @param resource the model's resource name, as {@link AgentModel#load} was given it
     * @throws IOException naming the URI when one is refused, missing, or the packed model is too large
     */
    static byte[] packed(Class<?> owner, String resource, byte[] gltf) throws IOException {
        JsonNode root;
        try {
            root = JSON.readTree(gltf);
        } catch (JacksonException e) {
            throw new IOException("model '" + resource + "' is not glTF JSON: " + e.getOriginalMessage(), e);
        }
        String folder = resource.contains("/") ? resource.substring(0, resource.lastIndexOf('/') + 1) : "";
        boolean changed = false;
        for (String array : new String[] {"buffers", "images"}) {
            JsonNode entries = root.get(array);
            if (entries == null || !entries.isArray()) {
                continue;
            }
            for (int i = 0; i < entries.size(); i++) {
                JsonNode uri = entries.get(i).get("uri");
                if (uri != null && uri.isString() && !uri.stringValue().startsWith("data:")
                        && entries.get(i) instanceof ObjectNode entry) {
                    String where = "model '" + resource + "' " + array + "[" + i + "].uri '" + uri.stringValue() + "'";
                    entry.put("uri", dataUri(owner, folder, uri.stringValue(), where));
                    changed = true;
                }
            }
        }
        if (!changed) {
            return gltf;
        }
        byte[] packed = root.toString().getBytes(StandardCharsets.UTF_8);
        if (packed.length > ModelSpec.MAX_MODEL_BYTES) {
            throw new IOException("model '" + resource + "' has " + packed.length + " bytes with its files embedded,"
                    + " at most " + ModelSpec.MAX_MODEL_BYTES + " may be sent (a .glb is a quarter smaller)");
        }
        return packed;
    }

    private static String dataUri(Class<?> owner, String folder, String uri, String where) throws IOException {
        String path = URLDecoder.decode(uri.replace("+", "%2B"), StandardCharsets.UTF_8);
        if (path.matches("^[A-Za-z][A-Za-z0-9+.-]*:.*") || path.startsWith("/") || path.startsWith("\\")) {
            throw new IOException(where + " is not a path relative to the model; only files next to the model"
                    + " (in its folder or below) are embedded, never a URL or an absolute path");
        }
        String within = withinFolder(path, where);
        String extension = within.substring(within.lastIndexOf('.') + 1).toLowerCase(Locale.ROOT);
        String type = MEDIA_TYPES.getOrDefault(extension, "application/octet-stream");
        String name = folder + within;
        try (InputStream in = owner.getResourceAsStream(name)) {
            if (in == null) {
                throw new IOException(where + ": no such file next to the model (looked for resource " + name + ")");
            }
            byte[] data = in.readNBytes(ModelSpec.MAX_MODEL_BYTES + 1);
            if (data.length > ModelSpec.MAX_MODEL_BYTES) {
                throw new IOException(where + " is larger than the " + ModelSpec.MAX_MODEL_BYTES
                        + " bytes a model may have");
            }
            return "data:" + type + ";base64," + Base64.getEncoder().encodeToString(data);
        }
    }

    /** The path with its '.' and '..' segments resolved, refused when it leaves the model's folder. */
    private static String withinFolder(String path, String where) throws IOException {
        Deque<String> segments = new ArrayDeque<>();
        for (String segment : path.replace('\\', '/').split("/", -1)) {
            if (segment.equals("..")) {
                if (segments.isEmpty()) {
                    throw new IOException(where + " leaves the model's folder; only files in it or below are"
                            + " embedded");
                }
                segments.removeLast();
            } else if (!segment.isEmpty() && !segment.equals(".")) {
                segments.addLast(segment);
            }
        }
        if (segments.isEmpty()) {
            throw new IOException(where + " names no file");
        }
        return String.join("/", segments);
    }
}
