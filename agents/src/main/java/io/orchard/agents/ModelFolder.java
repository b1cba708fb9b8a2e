package io.orchard.agents;

import io.orchard.protocol.StrictJson;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelSpec;
import java.io.IOException;
import java.io.InputStream;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Map;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Packs a glTF file exported the usual way, its buffers ({@code .bin}) and textures in files next
 * to it, into a zip of the model and those files ({@link ModelArchive}), the protocol's
 * {@code "format":"zip"}: the folder as the modelling tool wrote it, which viewers unpack. A URI is
 * resolved relative to the model's own folder among the agent's resources and must stay within it:
 * no scheme (so never the network), no absolute path, no {@code ..} that leaves the folder.
 */
final class ModelFolder {

    private static final JsonMapper JSON = StrictJson.builder().build();

    private ModelFolder() {
    }

    /**
     * The model and the files it refers to as a zip, or null when it refers to none.
     *
     * @param owner    the class whose resources hold the model
     * @param resource the model's resource name, as {@link AgentModel#load} was given it
     * @throws IOException naming the URI when one is refused, missing, or the files are too large
     */
    static byte[] zipped(Class<?> owner, String resource, byte[] gltf) throws IOException {
        JsonNode root;
        try {
            root = JSON.readTree(gltf);
        } catch (JacksonException e) {
            throw new IOException("model '" + resource + "' is not glTF JSON: " + e.getOriginalMessage(), e);
        }
        String folder = resource.contains("/") ? resource.substring(0, resource.lastIndexOf('/') + 1) : "";
        Map<String, byte[]> files = new LinkedHashMap<>();
        String name = resource.substring(folder.length());
        files.put(name, gltf);
        long total = gltf.length;
        for (String array : new String[] {"buffers", "images"}) {
            JsonNode entries = root.get(array);
            if (entries == null || !entries.isArray()) {
                continue;
            }
            for (int i = 0; i < entries.size(); i++) {
                JsonNode uri = entries.get(i).get("uri");
                if (uri != null && uri.isString() && !uri.stringValue().startsWith("data:")) {
                    String where = "model '" + resource + "' " + array + "[" + i + "].uri '" + uri.stringValue() + "'";
                    String path = path(uri.stringValue(), where);
                    if (!files.containsKey(path)) {
                        byte[] data = read(owner, folder + path, where);
                        total += data.length;
                        files.put(path, data);
                    }
                }
            }
        }
        if (files.size() == 1) {
            return null;
        }
        if (total > ModelSpec.MAX_MODEL_BYTES) {
            throw new IOException("model '" + resource + "' has " + total + " bytes with its files, at most "
                    + ModelSpec.MAX_MODEL_BYTES + " may be sent");
        }
        return ModelArchive.pack(files);
    }

    private static String path(String uri, String where) throws IOException {
        String path = URLDecoder.decode(uri.replace("+", "%2B"), StandardCharsets.UTF_8);
        if (path.matches("^[A-Za-z][A-Za-z0-9+.-]*:.*") || path.startsWith("/") || path.startsWith("\\")) {
            throw new IOException(where + " is not a path relative to the model; only files next to the model"
                    + " (in its folder or below) are sent, never a URL or an absolute path");
        }
        return withinFolder(path, where);
    }

    private static byte[] read(Class<?> owner, String name, String where) throws IOException {
        try (InputStream in = owner.getResourceAsStream(name)) {
            if (in == null) {
                throw new IOException(where + ": no such file next to the model (looked for resource " + name + ")");
            }
            byte[] data = in.readNBytes(ModelSpec.MAX_MODEL_BYTES + 1);
            if (data.length > ModelSpec.MAX_MODEL_BYTES) {
                throw new IOException(where + " is larger than the " + ModelSpec.MAX_MODEL_BYTES
                        + " bytes a model may have");
            }
            return data;
        }
    }

    /** The path with its '.' and '..' segments resolved, refused when it leaves the model's folder. */
    private static String withinFolder(String path, String where) throws IOException {
        Deque<String> segments = new ArrayDeque<>();
        for (String segment : path.replace('\\', '/').split("/", -1)) {
            if (segment.equals("..")) {
                if (segments.isEmpty()) {
                    throw new IOException(where + " leaves the model's folder; only files in it or below are"
                            + " sent");
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
