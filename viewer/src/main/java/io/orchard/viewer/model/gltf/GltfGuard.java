package io.orchard.viewer.model.gltf;

import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.DataUriImages;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Deque;
import java.util.Map;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.JsonNodeFactory;

/**
 * Inspects a glTF or GLB document before jME's loader reads it, and refuses what that loader
 * would handle dangerously: buffer or image URIs other than embedded {@code data:} URIs (the
 * loader would resolve them through the asset manager, reading files), JSON nested deeper or
 * longer than the limits ({@link GltfJson}), accessors that would allocate more values than the
 * limit, node hierarchies with cycles or shared children (the loader would recurse forever), more
 * nodes than the limit, and embedded images larger than the texture limit.
 */
final class GltfGuard {

    private static final int GLB_MAGIC = 0x46546C67;
    private static final int CHUNK_JSON = 0x4E4F534A;
    private static final Map<String, Integer> COMPONENTS = Map.of("SCALAR", 1, "VEC2", 2,
            "VEC3", 3, "VEC4", 4, "MAT2", 4, "MAT3", 9, "MAT4", 16);

    private final JsonNode root;
    private final ByteBuffer binChunk;
    private final ModelLimits limits;

    private GltfGuard(JsonNode root, ByteBuffer binChunk, ModelLimits limits) {
        this.root = root;
        this.binChunk = binChunk;
        this.limits = limits;
    }

    /** Checks a document; returns normally only if jME's loader may read it. */
    static void check(ModelFormat format, byte[] bytes, ModelLimits limits)
            throws ModelException {
        String json;
        ByteBuffer bin = null;
        if (format == ModelFormat.GLB) {
            ByteBuffer glb = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
            if (bytes.length < 20 || glb.getInt(0) != GLB_MAGIC) {
                throw new ModelException(Kind.MALFORMED, "GLB does not start with the 'glTF'"
                        + " header");
            }
            int version = glb.getInt(4);
            if (version != 2) {
                throw new ModelException(Kind.UNSUPPORTED, "GLB version " + version
                        + " is not supported; only glTF 2.0");
            }
            long declared = Integer.toUnsignedLong(glb.getInt(8));
            if (declared > bytes.length) {
                throw new ModelException(Kind.MALFORMED, "GLB declares " + declared
                        + " bytes but has only " + bytes.length + " (truncated?)");
            }
            // Walk the chunks exactly as jME's GlbLoader will, which allocates each chunk's
            // declared length before reading it: every chunk must lie within the bytes.
            json = null;
            long remaining = declared - 12;
            int at = 12;
            while (remaining > 0) {
                if (at + 8L > bytes.length) {
                    throw new ModelException(Kind.MALFORMED, "GLB chunk header at byte " + at
                            + " runs past the end of the file (truncated?)");
                }
                long length = Integer.toUnsignedLong(glb.getInt(at));
                int type = glb.getInt(at + 4);
                if (at + 8L + length > bytes.length) {
                    throw new ModelException(Kind.MALFORMED, "GLB chunk at byte " + at
                            + " declares " + length + " bytes but the file ends first");
                }
                if (type == CHUNK_JSON) {
                    if (json != null) {
                        throw new ModelException(Kind.MALFORMED, "GLB has a second JSON chunk"
                                + " at byte " + at);
                    }
                    json = utf8(bytes, at + 8, (int) length);
                } else if (json == null) {
                    throw new ModelException(Kind.MALFORMED, "GLB's first chunk is not JSON");
                } else if (bin == null) {
                    bin = ByteBuffer.wrap(bytes, at + 8, (int) length).slice();
                }
                at += 8 + (int) length;
                remaining -= 8 + length;
            }
            if (json == null) {
                throw new ModelException(Kind.MALFORMED, "GLB has no JSON chunk");
            }
        } else {
            json = utf8(bytes, 0, bytes.length);
        }
        JsonNode root = GltfJson.read(json, limits);
        if (!root.isObject()) {
            throw new ModelException(Kind.MALFORMED, "glTF JSON is not an object");
        }
        new GltfGuard(root, bin, limits).run(format);
    }

    private void run(ModelFormat format) throws ModelException {
        JsonNode asset = object(member(root, "asset"), "asset");
        JsonNode version = member(asset, "version");
        if (version == null || !version.isString() || !version.stringValue().startsWith("2.")) {
            throw new ModelException(Kind.UNSUPPORTED, "glTF asset.version " + show(version)
                    + " is not supported; only 2.x");
        }
        JsonNode buffers = array("buffers");
        for (int i = 0; i < buffers.size(); i++) {
            JsonNode buffer = object(buffers.get(i), "buffers[" + i + "]");
            JsonNode uri = member(buffer, "uri");
            if (uri == null && !(format == ModelFormat.GLB && i == 0)) {
                throw new ModelException(Kind.MALFORMED, "glTF buffers[" + i + "] has no uri");
            }
            if (uri != null) {
                requireEmbedded(uri, "buffers[" + i + "].uri");
            }
        }
        checkAccessors();
        checkNodes();
        checkImages(buffers);
    }

    private void checkAccessors() throws ModelException {
        long values = 0;
        JsonNode accessors = array("accessors");
        for (int i = 0; i < accessors.size(); i++) {
            String where = "accessors[" + i + "]";
            JsonNode accessor = object(accessors.get(i), where);
            JsonNode type = member(accessor, "type");
            Integer components = type != null && type.isString()
                    ? COMPONENTS.get(type.stringValue()) : null;
            if (components == null) {
                throw new ModelException(Kind.BAD_VALUE, "glTF " + where + ".type: expected"
                        + " SCALAR, VEC2..4 or MAT2..4 but found " + show(type));
            }
            values += count(member(accessor, "count"), where + ".count") * components;
            JsonNode sparse = member(accessor, "sparse");
            if (sparse != null && sparse.isObject()) {
                values += count(member(sparse, "count"), where + ".sparse.count")
                        * (components + 1);
            }
            if (values > limits.maxArrayValues()) {
                throw new ModelException(Kind.TOO_LARGE, "glTF " + where + ": the accessors"
                        + " hold more than " + limits.maxArrayValues() + " values");
            }
        }
    }

    /** Nodes form a forest within the depth limit; nodes plus mesh parts within the limit. */
    private void checkNodes() throws ModelException {
        JsonNode nodes = array("nodes");
        JsonNode meshes = array("meshes");
        long spatials = nodes.size();
        int[] parent = new int[nodes.size()];
        Arrays.fill(parent, -1);
        for (int i = 0; i < nodes.size(); i++) {
            JsonNode node = object(nodes.get(i), "nodes[" + i + "]");
            JsonNode mesh = member(node, "mesh");
            if (mesh != null) {
                int m = index(mesh, meshes.size(), "nodes[" + i + "].mesh");
                JsonNode primitives = member(object(meshes.get(m), "meshes[" + m + "]"),
                        "primitives");
                spatials += primitives != null && primitives.isArray() ? primitives.size() : 0;
            }
            JsonNode children = member(node, "children");
            if (children == null) {
                continue;
            }
            if (!children.isArray()) {
                throw new ModelException(Kind.MALFORMED, "glTF nodes[" + i + "].children is not"
                        + " an array");
            }
            for (JsonNode child : children.values()) {
                int c = index(child, nodes.size(), "nodes[" + i + "].children");
                if (parent[c] >= 0 || c == i) {
                    throw new ModelException(Kind.MALFORMED, "glTF nodes[" + c + "] is a child of"
                            + " more than one node (or of itself); glTF nodes form a tree");
                }
                parent[c] = i;
            }
        }
        if (spatials > limits.maxNodes()) {
            throw new ModelException(Kind.TOO_LARGE, "glTF has " + spatials + " nodes and mesh"
                    + " parts, more than the limit of " + limits.maxNodes());
        }
        int reached = 0;
        Deque<int[]> pending = new ArrayDeque<>();
        for (int i = 0; i < nodes.size(); i++) {
            if (parent[i] < 0) {
                pending.push(new int[] {i, 1});
            }
        }
        while (!pending.isEmpty()) {
            int[] entry = pending.pop();
            reached++;
            if (entry[1] > limits.maxDepth()) {
                throw new ModelException(Kind.TOO_LARGE, "glTF nodes[" + entry[0] + "] is nested"
                        + " deeper than " + limits.maxDepth() + " levels");
            }
            JsonNode children = member(nodes.get(entry[0]), "children");
            if (children != null) {
                for (JsonNode child : children.values()) {
                    pending.push(new int[] {child.intValue(), entry[1] + 1});
                }
            }
        }
        if (reached != nodes.size()) {
            throw new ModelException(Kind.MALFORMED, "glTF node hierarchy has a cycle");
        }
        JsonNode scenes = array("scenes");
        for (int i = 0; i < scenes.size(); i++) {
            JsonNode sceneNodes = member(object(scenes.get(i), "scenes[" + i + "]"), "nodes");
            if (sceneNodes != null && sceneNodes.isArray()) {
                for (JsonNode n : sceneNodes.values()) {
                    index(n, nodes.size(), "scenes[" + i + "].nodes");
                }
            }
        }
    }

    private void checkImages(JsonNode buffers) throws ModelException {
        JsonNode images = array("images");
        JsonNode views = array("bufferViews");
        for (int i = 0; i < images.size(); i++) {
            String where = "glTF images[" + i + "]";
            JsonNode image = object(images.get(i), "images[" + i + "]");
            byte[] data = null;
            JsonNode uri = member(image, "uri");
            JsonNode view = member(image, "bufferView");
            if (uri != null) {
                requireEmbedded(uri, "images[" + i + "].uri");
                data = DataUriImages.bytes(uri.stringValue(), where);
            } else if (view != null) {
                data = bufferView(views, buffers, index(view, views.size(),
                        "images[" + i + "].bufferView"));
            }
            if (data != null && data.length >= 8) {
                int[] size = sizeIfKnown(data, where);
                if (size != null) {
                    DataUriImages.checkSize(size[0], size[1], limits.maxTextureSize(), where);
                }
            }
        }
    }

    private static int[] sizeIfKnown(byte[] data, String where) throws ModelException {
        try {
            return DataUriImages.size(data, where);
        } catch (ModelException e) {
            if (e.kind() == Kind.UNSUPPORTED) {
                return null; // KTX2, WebP and the like: the loader decides
            }
            throw e;
        }
    }

    private byte[] bufferView(JsonNode views, JsonNode buffers, int v) throws ModelException {
        JsonNode view = object(views.get(v), "bufferViews[" + v + "]");
        int b = index(member(view, "buffer"), buffers.size(), "bufferViews[" + v + "].buffer");
        JsonNode byteOffset = member(view, "byteOffset");
        long offset = byteOffset == null ? 0
                : count(byteOffset, "bufferViews[" + v + "].byteOffset");
        long length = count(member(view, "byteLength"), "bufferViews[" + v + "].byteLength");
        JsonNode uri = member(object(buffers.get(b), "buffers[" + b + "]"), "uri");
        byte[] buffer;
        if (uri == null) {
            if (binChunk == null) {
                throw new ModelException(Kind.MALFORMED, "glTF buffers[" + b + "] has no uri and"
                        + " the file has no BIN chunk");
            }
            buffer = new byte[binChunk.remaining()];
            binChunk.duplicate().get(buffer);
        } else {
            buffer = DataUriImages.bytes(uri.stringValue(), "glTF buffers[" + b + "].uri");
        }
        if (offset + length > buffer.length) {
            throw new ModelException(Kind.MALFORMED, "glTF bufferViews[" + v + "] reaches byte "
                    + (offset + length) + " of a buffer of " + buffer.length + " bytes");
        }
        byte[] slice = new byte[(int) length];
        System.arraycopy(buffer, (int) offset, slice, 0, (int) length);
        return slice;
    }

    private static void requireEmbedded(JsonNode uri, String where) throws ModelException {
        if (!uri.isString()) {
            throw new ModelException(Kind.MALFORMED, "glTF " + where + " is not a string");
        }
        String text = uri.stringValue();
        if (!DataUriImages.isDataUri(text)) {
            throw new ModelException(Kind.UNSAFE, "glTF " + where + " '" + abbreviate(text)
                    + "' refers to an external resource; only embedded data: URIs are accepted"
                    + " (use .glb or embed the data)");
        }
    }

    /** A top-level array, empty when absent or null. */
    private JsonNode array(String name) throws ModelException {
        JsonNode value = member(root, name);
        if (value == null) {
            return JsonNodeFactory.instance.arrayNode();
        }
        if (!value.isArray()) {
            throw new ModelException(Kind.MALFORMED, "glTF " + name + " is not an array");
        }
        return value;
    }

    /** A member's value; null when it is absent or JSON null, as glTF means the same by both. */
    private static JsonNode member(JsonNode object, String name) {
        JsonNode value = object.get(name);
        return value == null || value.isNull() ? null : value;
    }

    private static JsonNode object(JsonNode value, String where) throws ModelException {
        if (value == null || !value.isObject()) {
            throw new ModelException(Kind.MALFORMED, "glTF " + where + " is missing or not an"
                    + " object");
        }
        return value;
    }

    private static long count(JsonNode value, String where) throws ModelException {
        double d = value != null && value.isNumber() ? value.doubleValue() : -1;
        if (d < 0 || d != Math.floor(d) || d > Integer.MAX_VALUE) {
            throw new ModelException(Kind.BAD_VALUE, "glTF " + where + ": expected a count but"
                    + " found " + show(value));
        }
        return (long) d;
    }

    private static int index(JsonNode value, int size, String where) throws ModelException {
        double d = value != null && value.isNumber() ? value.doubleValue() : -1;
        if (d != Math.floor(d) || d < 0 || d >= size) {
            throw new ModelException(Kind.BAD_VALUE, "glTF " + where + ": index " + show(value)
                    + " is not one of the " + size + " entries");
        }
        return (int) d;
    }

    /** A value as a message shows it: text without quotes, anything else as JSON. */
    private static String show(JsonNode value) {
        if (value == null) {
            return "null";
        }
        String text = value.isString() ? value.stringValue() : value.toString();
        return abbreviate(text);
    }

    private static String utf8(byte[] bytes, int offset, int length) throws ModelException {
        try {
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes, offset, length)).toString();
        } catch (CharacterCodingException e) {
            throw new ModelException(Kind.MALFORMED, "glTF JSON is not valid UTF-8", e);
        }
    }

    private static String abbreviate(String text) {
        return text.length() <= 60 ? text : text.substring(0, 57) + "...";
    }
}
