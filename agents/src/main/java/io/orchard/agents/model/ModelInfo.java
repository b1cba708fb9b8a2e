package io.orchard.agents.model;

import io.orchard.protocol.StrictJson;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Vec3;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * What a model file holds, read offline, without a viewer and without OpenGL: the names an agent
 * registers ({@code RegisterJoint}, {@code RegisterTimeSensor}), the model's bounding box and its
 * units. glTF and GLB: every node is a joint, named as the file names it or {@code node#i} by its
 * index when it has no name, as viewers name it; every animation is a clip ({@code clip#i} when
 * unnamed); the box is that of the meshes' positions as the nodes place them, in metres, glTF's
 * unit. X3D and VRML97: every DEF'd Transform is a joint, every DEF'd TimeSensor a clip; the box is
 * that of the shapes (Box, Sphere, Cylinder, Cone and coordinates) as the Transforms place them, in
 * the file's units (X3D's {@code <unit category='length'>}, otherwise metres). A zip ({@link
 * ModelArchive}) is read through its model file.
 *
 * <pre>{@code
 * ModelInfo info = ModelInfo.read(Path.of("models/Cat.gltf"));
 * info.joints();  // [Cat, Shoulder.L_CatArmature, node#7, ...]
 * info.clips();   // [Armature|Walk, clip#1]
 * info.size();    // Vec3[x=0.41, y=0.62, z=1.2], in info.units()
 * }</pre>
 *
 * @param file    the file's name, as given
 * @param format  the model file's format (of the model file inside, for a zip)
 * @param inside  for a zip, the model file's path in it; otherwise null
 * @param roots   the names of the top-level nodes: the node an agent names itself after is usually one
 * @param joints  the names {@code RegisterJoint} may give, in file order
 * @param clips   the names {@code RegisterTimeSensor} may give, in file order
 * @param min     the lowest corner of the bounding box, in the file's units; null when nothing was measured
 * @param max     the highest corner; null when nothing was measured
 * @param units   the file's length unit
 * @param notes   what was not read, or is worth knowing (a model as tall as a house, skipped prototypes)
 */
public record ModelInfo(String file, ModelFormat format, @Nullable String inside, List<String> roots,
                        List<String> joints, List<String> clips, @Nullable Vec3 min, @Nullable Vec3 max, Units units,
                        List<String> notes) {

    /**
     * A model's length unit.
     *
     * @param name     its name, such as {@code metre} or {@code centimetre}
     * @param metres   how many metres one unit is
     * @param declared whether the file says so (glTF always does, by its specification), or it is taken as metres
     */
    public record Units(String name, double metres, boolean declared) {
    }

    private static final JsonMapper JSON = StrictJson.builder().build();
    private static final Set<String> JOINT_TYPES = Set.of("Transform", "HAnimJoint", "HAnimSegment", "HAnimHumanoid");
    /** The largest file read. */
    private static final long READ_AT_MOST = 64L * 1024 * 1024;
    /** Taller than this, in metres, a model is likely authored in centimetres. */
    private static final double HOUSE = 20;

    /** Copies the lists. */
    public ModelInfo {
        roots = List.copyOf(roots);
        joints = List.copyOf(joints);
        clips = List.copyOf(clips);
        notes = List.copyOf(notes);
    }

    /**
     * Reads a model file: {@code .gltf}, {@code .glb}, {@code .x3d}, {@code .wrl} or {@code .zip}.
     *
     * @throws IOException naming the file when it cannot be read, is larger than a model may be, or is
     *                     not a model of its extension
     */
    public static ModelInfo read(Path path) throws IOException {
        String name = path.getFileName().toString();
        ModelFormat format = formatOf(name);
        long size = Files.size(path);
        if (size > READ_AT_MOST) {
            throw new IOException(path + " has " + size + " bytes; model-info reads at most " + READ_AT_MOST
                    + " (and a model sent to a server has at most " + ModelSpec.MAX_MODEL_BYTES + ")");
        }
        ModelInfo info = of(name, format, Files.readAllBytes(path));
        if (size <= ModelSpec.MAX_MODEL_BYTES) {
            return info;
        }
        List<String> notes = new ArrayList<>(info.notes);
        notes.add(size + " bytes: larger than the " + ModelSpec.MAX_MODEL_BYTES + " a model sent to a server may have");
        return new ModelInfo(info.file, info.format, info.inside, info.roots, info.joints, info.clips, info.min,
                info.max, info.units, notes);
    }

    /**
     * Reads a model from its bytes.
     *
     * @param file   its name, for messages
     * @param format its format; {@link ModelFormat#ZIP} for a zip of a model's files
     * @throws IOException naming the file when it is not a model of that format
     */
    public static ModelInfo of(String file, ModelFormat format, byte[] bytes) throws IOException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(format, "format");
        try {
            return switch (format) {
                case ZIP -> {
                    ModelArchive archive = ModelArchive.read(bytes);
                    ModelInfo model = of(file, archive.modelFormat(), archive.modelBytes());
                    yield new ModelInfo(file, model.format, archive.modelPath(), model.roots, model.joints,
                            model.clips, model.min, model.max, model.units, model.notes);
                }
                case GLTF -> gltf(file, format, new String(bytes, StandardCharsets.UTF_8));
                case GLB -> gltf(file, format, glbJson(file, bytes));
                case X3D -> scene(file, format, SceneReader.x3d(bytes));
                case VRML97 -> scene(file, format, SceneReader.vrml(bytes));
                case BUNDLED -> throw new IOException(file + ": a bundled model is named, not read");
            };
        } catch (IllegalArgumentException | JacksonException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        } catch (IOException e) {
            throw e.getMessage() != null && e.getMessage().startsWith(file) ? e
                    : new IOException(file + ": " + e.getMessage(), e);
        }
    }

    /**
     * The format a file's extension stands for: {@code .gltf}, {@code .glb}, {@code .x3d}, {@code .wrl},
     * {@code .zip}.
     *
     * @throws IOException naming the extension and those known
     */
    public static ModelFormat formatOf(String name) throws IOException {
        String lower = name.toLowerCase(Locale.ROOT);
        int dot = lower.lastIndexOf('.');
        ModelFormat format = dot < 0 ? null : lower.endsWith(".zip") ? ModelFormat.ZIP
                : ModelArchive.MODEL_EXTENSIONS.get(lower.substring(dot));
        if (format == null) {
            throw new IOException(name + ": expected a model file, .gltf, .glb, .x3d, .wrl or .zip");
        }
        return format;
    }

    /** The bounding box's size, in the file's units; null when nothing was measured. */
    public @Nullable Vec3 size() {
        return min == null ? null : new Vec3(max.x() - min.x(), max.y() - min.y(), max.z() - min.z());
    }

    private static ModelInfo gltf(String file, ModelFormat format, String json) throws IOException {
        JsonNode root = JSON.readTree(json);
        if (root == null || !root.isObject()) {
            throw new IOException(file + ": glTF JSON is not an object");
        }
        List<String> joints = names(root.get("nodes"), "node#");
        List<String> clips = names(root.get("animations"), "clip#");
        JsonNode scenes = root.get("scenes");
        int scene = root.path("scene").asInt(0);
        List<Integer> top = new ArrayList<>();
        if (scenes != null && scenes.isArray() && scene < scenes.size()) {
            scenes.get(scene).path("nodes").forEach(n -> top.add(n.asInt()));
        } else {
            for (int i = 0; i < joints.size(); i++) {
                top.add(i);
            }
        }
        Extent extent = new Extent();
        Set<Integer> visited = new LinkedHashSet<>();
        for (int node : top) {
            gltfNode(root, node, Extent.IDENTITY, extent, visited);
        }
        List<String> roots = top.stream().filter(i -> i >= 0 && i < joints.size()).map(joints::get).toList();
        return finish(file, format, roots, joints, clips, extent, new Units("metre", 1, true), new ArrayList<>());
    }

    private static List<String> names(JsonNode array, String prefix) {
        List<String> names = new ArrayList<>();
        for (int i = 0; array != null && array.isArray() && i < array.size(); i++) {
            JsonNode name = array.get(i).get("name");
            names.add(name != null && name.isString() && !name.stringValue().isEmpty() ? name.stringValue()
                    : prefix + i);
        }
        return names;
    }

    private static void gltfNode(JsonNode root, int index, double[] parent, Extent extent, Set<Integer> visited) {
        JsonNode node = root.path("nodes").path(index);
        if (!node.isObject() || !visited.add(index)) {
            return;
        }
        double[] local;
        if (node.has("matrix") && node.get("matrix").size() == 16) {
            local = new double[16];
            for (int i = 0; i < 16; i++) {
                local[i] = node.get("matrix").get(i).asDouble();
            }
        } else {
            local = Extent.trs(numbers(node.get("translation"), 0, 0, 0), numbers(node.get("rotation"), 0, 0, 0, 1),
                    numbers(node.get("scale"), 1, 1, 1));
        }
        double[] m = Extent.multiply(parent, local);
        if (node.has("mesh")) {
            for (JsonNode primitive : root.path("meshes").path(node.get("mesh").asInt()).path("primitives")) {
                JsonNode accessor = root.path("accessors").path(primitive.path("attributes").path("POSITION").asInt(-1));
                if (accessor.has("min") && accessor.has("max")) {
                    extent.addBox(m, numbers(accessor.get("min"), 0, 0, 0), numbers(accessor.get("max"), 0, 0, 0));
                }
            }
        }
        for (JsonNode child : node.path("children")) {
            gltfNode(root, child.asInt(), m, extent, visited);
        }
    }

    private static double[] numbers(JsonNode array, double... defaults) {
        if (array == null || !array.isArray() || array.size() != defaults.length) {
            return defaults;
        }
        double[] values = new double[defaults.length];
        for (int i = 0; i < values.length; i++) {
            values[i] = array.get(i).asDouble();
        }
        return values;
    }

    private static String glbJson(String file, byte[] bytes) throws IOException {
        ByteBuffer glb = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        if (bytes.length < 20 || glb.getInt(0) != 0x46546C67 || glb.getInt(16) != 0x4E4F534A) {
            throw new IOException(file + ": not a binary glTF (no 'glTF' header and JSON chunk)");
        }
        int length = glb.getInt(12);
        if (length < 0 || 20L + length > bytes.length) {
            throw new IOException(file + ": its JSON chunk runs past the end of the file");
        }
        return new String(bytes, 20, length, StandardCharsets.UTF_8);
    }

    private static ModelInfo scene(String file, ModelFormat format, SceneReader.Scene scene) {
        List<String> roots = new ArrayList<>();
        Set<String> joints = new LinkedHashSet<>();
        Set<String> clips = new LinkedHashSet<>();
        Extent extent = new Extent();
        for (Node node : scene.roots()) {
            if (node.def != null && JOINT_TYPES.contains(node.type)) {
                roots.add(node.def);
            }
            walk(node, Extent.IDENTITY, extent, joints, clips, 0);
        }
        return finish(file, format, roots, List.copyOf(joints), List.copyOf(clips), extent,
                new Units(scene.unitName(), scene.metresPerUnit(), scene.unitDeclared()), scene.notes());
    }

    private static void walk(Node node, double[] parent, Extent extent, Set<String> joints, Set<String> clips,
                             int depth) {
        if (depth > 256) {
            return;
        }
        double[] m = parent;
        switch (node.type) {
            case "Transform", "HAnimJoint", "HAnimSegment", "HAnimHumanoid" -> {
                if (node.def != null) {
                    joints.add(node.def);
                }
                double[] r = node.numbers("rotation", 0, 0, 1, 0);
                m = Extent.multiply(parent, Extent.trs(node.numbers("translation", 0, 0, 0),
                        r.length == 4 ? Extent.axisAngle(r[0], r[1], r[2], r[3]) : new double[] {0, 0, 0, 1},
                        node.numbers("scale", 1, 1, 1)));
            }
            case "TimeSensor" -> {
                if (node.def != null) {
                    clips.add(node.def);
                }
            }
            case "Box" -> {
                double[] s = node.numbers("size", 2, 2, 2);
                extent.addBox(m, new double[] {-s[0] / 2, -s[1] / 2, -s[2] / 2}, new double[] {s[0] / 2, s[1] / 2,
                    s[2] / 2});
            }
            case "Sphere" -> {
                double r = node.numbers("radius", 1)[0];
                extent.addBox(m, new double[] {-r, -r, -r}, new double[] {r, r, r});
            }
            case "Cylinder", "Cone" -> {
                double r = node.numbers(node.type.equals("Cone") ? "bottomRadius" : "radius", 1)[0];
                double h = node.numbers("height", 2)[0] / 2;
                extent.addBox(m, new double[] {-r, -h, -r}, new double[] {r, h, r});
            }
            case "Coordinate" -> {
                double[] p = node.numbers("point");
                for (int i = 0; i + 2 < p.length; i += 3) {
                    extent.add(m, p[i], p[i + 1], p[i + 2]);
                }
            }
            default -> { }
        }
        for (Map.Entry<String, List<Node>> field : node.children.entrySet()) {
            for (Node child : field.getValue()) {
                walk(child, m, extent, joints, clips, depth + 1);
            }
        }
    }

    private static ModelInfo finish(String file, ModelFormat format, List<String> roots, List<String> joints,
                                    List<String> clips, Extent extent, Units units, List<String> notes) {
        Vec3 min = extent.isEmpty() ? null : new Vec3(extent.min[0], extent.min[1], extent.min[2]);
        Vec3 max = extent.isEmpty() ? null : new Vec3(extent.max[0], extent.max[1], extent.max[2]);
        List<String> all = new ArrayList<>(notes);
        if (min == null) {
            all.add("nothing was measured: no mesh, shape or coordinates this reader knows");
        } else if ((max.y() - min.y()) * units.metres() > HOUSE) {
            all.add(String.format(Locale.ROOT, "%.1f m tall: perhaps authored in centimetres; viewers fit a model"
                    + " to its agent's body unless it asks to be shown as authored", (max.y() - min.y()) * units.metres()));
        }
        return new ModelInfo(file, format, null, roots, joints, clips, min, max, units, all);
    }

    /** The model as text for a person: one thing a line. */
    public String toText() {
        StringBuilder out = new StringBuilder();
        out.append(file).append(": ").append(format.wireName()).append(inside == null ? "" : " (" + inside
                + " in the zip)").append('\n');
        out.append("roots: ").append(String.join(", ", roots)).append('\n');
        out.append("joints (").append(joints.size()).append("): ").append(String.join(", ", joints)).append('\n');
        out.append("clips (").append(clips.size()).append("): ").append(String.join(", ", clips)).append('\n');
        Vec3 size = size();
        if (size != null) {
            out.append(String.format(Locale.ROOT, "size: %.4g x %.4g x %.4g %s (x, y up, z); from (%.4g, %.4g,"
                    + " %.4g) to (%.4g, %.4g, %.4g)%n", size.x(), size.y(), size.z(), plural(units.name()), min.x(),
                    min.y(), min.z(), max.x(), max.y(), max.z()));
        }
        out.append(String.format(Locale.ROOT, "units: %s (%s m)%s%n", units.name(), units.metres(), units.declared()
                ? "" : ", not declared: taken as metres"));
        for (String note : notes) {
            out.append("note: ").append(note).append('\n');
        }
        return out.toString();
    }

    private static String plural(String unit) {
        return unit.endsWith("s") ? unit : unit + "s";
    }

    /** The model as JSON, as {@code ./orchard model-info --json} prints it (docs/agents.md names every field). */
    public String toJson() {
        ObjectNode json = JSON.createObjectNode();
        json.put("file", file);
        json.put("format", format.wireName());
        json.put("inside", inside);
        array(json.putArray("roots"), roots);
        array(json.putArray("joints"), joints);
        array(json.putArray("clips"), clips);
        Vec3 size = size();
        if (size == null) {
            json.putNull("bounds");
        } else {
            ObjectNode bounds = json.putObject("bounds");
            bounds.putArray("min").add(min.x()).add(min.y()).add(min.z());
            bounds.putArray("max").add(max.x()).add(max.y()).add(max.z());
            bounds.putArray("size").add(size.x()).add(size.y()).add(size.z());
        }
        ObjectNode unit = json.putObject("units");
        unit.put("name", units.name());
        unit.put("metres", units.metres());
        unit.put("declared", units.declared());
        array(json.putArray("notes"), notes);
        return json.toString();
    }

    private static void array(ArrayNode array, List<String> values) {
        values.forEach(array::add);
    }
}
