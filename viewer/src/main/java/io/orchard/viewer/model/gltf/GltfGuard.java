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
import java.util.List;
import java.util.Map;

/**
 * Inspects a glTF or GLB document before jME's loader reads it, and refuses what that loader
 * would handle dangerously: buffer or image URIs other than embedded {@code data:} URIs (the
 * loader would resolve them through the asset manager, reading files), JSON nested deeper than
 * the limit, accessors that would allocate more values than the limit, node hierarchies with
 * cycles or shared children (the loader would recurse forever), more nodes than the limit, and
 * embedded images larger than the texture limit.
 */
final class GltfGuard {

    private static final int GLB_MAGIC = 0x46546C67;
    private static final int CHUNK_JSON = 0x4E4F534A;
    private static final Map<String, Integer> COMPONENTS = Map.of("SCALAR", 1, "VEC2", 2,
            "VEC3", 3, "VEC4", 4, "MAT2", 4, "MAT3", 9, "MAT4", 16);

    private final Map<String, Object> root;
    private final ByteBuffer binChunk;
    private final ModelLimits limits;

    private GltfGuard(Map<String, Object> root, ByteBuffer binChunk, ModelLimits limits) {
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
        Object document = JsonTree.parse(json, limits.maxDepth());
        if (!(document instanceof Map<?, ?>)) {
            throw new ModelException(Kind.MALFORMED, "glTF JSON is not an object");
        }
        @SuppressWarnings("unchecked")
        Map<String, Object> root = (Map<String, Object>) document;
        new GltfGuard(root, bin, limits).run(format);
    }

    private void run(ModelFormat format) throws ModelException {
        Map<String, Object> asset = object(root.get("asset"), "asset");
        Object version = asset.get("version");
        if (!(version instanceof String v) || !v.startsWith("2.")) {
            throw new ModelException(Kind.UNSUPPORTED, "glTF asset.version " + version
                    + " is not supported; only 2.x");
        }
        List<Object> buffers = array("buffers");
        for (int i = 0; i < buffers.size(); i++) {
            Map<String, Object> buffer = object(buffers.get(i), "buffers[" + i + "]");
            Object uri = buffer.get("uri");
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
        List<Object> accessors = array("accessors");
        for (int i = 0; i < accessors.size(); i++) {
            String where = "accessors[" + i + "]";
            Map<String, Object> accessor = object(accessors.get(i), where);
            Integer components = COMPONENTS.get(String.valueOf(accessor.get("type")));
            if (components == null) {
                throw new ModelException(Kind.BAD_VALUE, "glTF " + where + ".type: expected"
                        + " SCALAR, VEC2..4 or MAT2..4 but found " + accessor.get("type"));
            }
            values += count(accessor.get("count"), where + ".count") * components;
            Object sparse = accessor.get("sparse");
            if (sparse instanceof Map<?, ?> s) {
                values += count(s.get("count"), where + ".sparse.count") * (components + 1);
            }
            if (values > limits.maxArrayValues()) {
                throw new ModelException(Kind.TOO_LARGE, "glTF " + where + ": the accessors"
                        + " hold more than " + limits.maxArrayValues() + " values");
            }
        }
    }

    /** Nodes form a forest within the depth limit; nodes plus mesh parts within the limit. */
    private void checkNodes() throws ModelException {
        List<Object> nodes = array("nodes");
        List<Object> meshes = array("meshes");
        long spatials = nodes.size();
        int[] parent = new int[nodes.size()];
        Arrays.fill(parent, -1);
        for (int i = 0; i < nodes.size(); i++) {
            Map<String, Object> node = object(nodes.get(i), "nodes[" + i + "]");
            Object mesh = node.get("mesh");
            if (mesh != null) {
                int m = index(mesh, meshes.size(), "nodes[" + i + "].mesh");
                Object primitives = object(meshes.get(m), "meshes[" + m + "]").get("primitives");
                spatials += primitives instanceof List<?> list ? list.size() : 0;
            }
            Object children = node.get("children");
            if (children == null) {
                continue;
            }
            if (!(children instanceof List<?> list)) {
                throw new ModelException(Kind.MALFORMED, "glTF nodes[" + i + "].children is not"
                        + " an array");
            }
            for (Object child : list) {
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
            Object children = ((Map<?, ?>) nodes.get(entry[0])).get("children");
            if (children instanceof List<?> list) {
                for (Object child : list) {
                    pending.push(new int[] {((Double) child).intValue(), entry[1] + 1});
                }
            }
        }
        if (reached != nodes.size()) {
            throw new ModelException(Kind.MALFORMED, "glTF node hierarchy has a cycle");
        }
        List<Object> scenes = array("scenes");
        for (int i = 0; i < scenes.size(); i++) {
            Object sceneNodes = object(scenes.get(i), "scenes[" + i + "]").get("nodes");
            if (sceneNodes instanceof List<?> list) {
                for (Object n : list) {
                    index(n, nodes.size(), "scenes[" + i + "].nodes");
                }
            }
        }
    }

    private void checkImages(List<Object> buffers) throws ModelException {
        List<Object> images = array("images");
        List<Object> views = array("bufferViews");
        for (int i = 0; i < images.size(); i++) {
            String where = "glTF images[" + i + "]";
            Map<String, Object> image = object(images.get(i), "images[" + i + "]");
            byte[] data = null;
            Object uri = image.get("uri");
            if (uri != null) {
                requireEmbedded(uri, "images[" + i + "].uri");
                data = DataUriImages.bytes((String) uri, where);
            } else if (image.get("bufferView") != null) {
                data = bufferView(views, buffers, index(image.get("bufferView"), views.size(),
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

    private byte[] bufferView(List<Object> views, List<Object> buffers, int v)
            throws ModelException {
        Map<String, Object> view = object(views.get(v), "bufferViews[" + v + "]");
        int b = index(view.get("buffer"), buffers.size(), "bufferViews[" + v + "].buffer");
        long offset = view.get("byteOffset") == null ? 0
                : count(view.get("byteOffset"), "bufferViews[" + v + "].byteOffset");
        long length = count(view.get("byteLength"), "bufferViews[" + v + "].byteLength");
        Object uri = object(buffers.get(b), "buffers[" + b + "]").get("uri");
        byte[] buffer;
        if (uri == null) {
            if (binChunk == null) {
                throw new ModelException(Kind.MALFORMED, "glTF buffers[" + b + "] has no uri and"
                        + " the file has no BIN chunk");
            }
            buffer = new byte[binChunk.remaining()];
            binChunk.duplicate().get(buffer);
        } else {
            buffer = DataUriImages.bytes((String) uri, "glTF buffers[" + b + "].uri");
        }
        if (offset + length > buffer.length) {
            throw new ModelException(Kind.MALFORMED, "glTF bufferViews[" + v + "] reaches byte "
                    + (offset + length) + " of a buffer of " + buffer.length + " bytes");
        }
        byte[] slice = new byte[(int) length];
        System.arraycopy(buffer, (int) offset, slice, 0, (int) length);
        return slice;
    }

    private static void requireEmbedded(Object uri, String where) throws ModelException {
        if (!(uri instanceof String text)) {
            throw new ModelException(Kind.MALFORMED, "glTF " + where + " is not a string");
        }
        if (!DataUriImages.isDataUri(text)) {
            throw new ModelException(Kind.UNSAFE, "glTF " + where + " '" + abbreviate(text)
                    + "' refers to an external resource; only embedded data: URIs are accepted"
                    + " (use .glb or embed the data)");
        }
    }

    private List<Object> array(String name) throws ModelException {
        Object value = root.get(name);
        if (value == null) {
            return List.of();
        }
        if (!(value instanceof List<?>)) {
            throw new ModelException(Kind.MALFORMED, "glTF " + name + " is not an array");
        }
        @SuppressWarnings("unchecked")
        List<Object> list = (List<Object>) value;
        return list;
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> object(Object value, String where) throws ModelException {
        if (!(value instanceof Map<?, ?>)) {
            throw new ModelException(Kind.MALFORMED, "glTF " + where + " is missing or not an"
                    + " object");
        }
        return (Map<String, Object>) value;
    }

    private static long count(Object value, String where) throws ModelException {
        if (!(value instanceof Double d) || d < 0 || d != Math.floor(d) || d > Integer.MAX_VALUE) {
            throw new ModelException(Kind.BAD_VALUE, "glTF " + where + ": expected a count but"
                    + " found " + value);
        }
        return d.longValue();
    }

    private static int index(Object value, int size, String where) throws ModelException {
        if (!(value instanceof Double d) || d != Math.floor(d) || d < 0 || d >= size) {
            throw new ModelException(Kind.BAD_VALUE, "glTF " + where + ": index " + value
                    + " is not one of the " + size + " entries");
        }
        return d.intValue();
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
