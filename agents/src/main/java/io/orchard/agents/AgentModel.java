package io.orchard.agents;

import io.orchard.protocol.StrictJson;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * An agent's visual model as it travels with the agent: the bytes of an X3D, VRML97 or glTF file,
 * read from the agent's resources and sent at registration, so that viewers show the agent as its
 * author designed it.
 *
 * <p>Before registering, the controller checks that the model has what the paper requires
 * ({@link #check}): a Transform named after the agent, and a node for each joint and time sensor
 * the agent registers. The check is a light one: it reads the nodes' DEF names (X3D, VRML97) or
 * the names in a glTF file (an unnamed node or clip as {@code node#i} or {@code clip#i}, by its index, as viewers
 * name it), without loading the model.
 *
 * <p>A .gltf whose buffers and textures are files next to it, as modelling tools export it, is sent as a zip of the
 * model and those files ({@code "format":"zip"}): each is read from the model's own folder among the resources (never
 * from elsewhere, never from the network).
 *
 * <pre>{@code
 * AgentModel model = AgentModel.load(Dwarf.class, "models/Dwarf.x3d");
 * model.check("Dwarf", List.of("LeftKnee"), List.of("DwarfTSWalk")); // throws, naming what is missing
 * ModelSpec spec = model.spec();
 * }</pre>
 */
public final class AgentModel {

    private static final Pattern X3D_NODE = Pattern.compile(
            "<\\s*([A-Za-z][\\w:]*)\\b[^>]*?\\bDEF\\s*=\\s*([\"'])(.*?)\\2", Pattern.DOTALL);
    private static final Pattern VRML_NODE = Pattern.compile("\\bDEF\\s+([^\\s{}\\[\\].#\"',]+)\\s+([A-Za-z_]\\w*)");
    private static final Pattern GLTF_NAME = Pattern.compile("\"name\"\\s*:\\s*\"((?:[^\"\\\\]|\\\\.)*)\"");
    private static final List<String> JOINT_TYPES = List.of("Transform", "HAnimJoint", "HAnimSegment", "HAnimHumanoid");
    private static final String GLTF_TYPE = "named";
    private static final JsonMapper INDEX_READER = StrictJson.builder().build();

    private final ModelFormat format;
    private final ModelFormat modelFormat;
    private final byte[] bytes;
    private final String source;
    private final Map<String, String> nodes;

    private AgentModel(ModelFormat format, byte[] bytes, String source) {
        this.format = format;
        this.bytes = bytes;
        this.source = source;
        ModelArchive archive = format == ModelFormat.ZIP ? ModelArchive.read(bytes) : null;
        this.modelFormat = archive == null ? format : archive.modelFormat();
        this.nodes = Collections.unmodifiableMap(scan(modelFormat, archive == null ? bytes : archive.modelBytes()));
    }

    /**
     * Reads a model from a resource.
     *
     * @param owner    the class the resource lies next to (the agent's class)
     * @param resource the resource's name, relative to the owner's package or absolute with a leading '/'
     * @throws IOException when the resource is missing or cannot be read (the message names where it was looked for)
     */
    public static AgentModel load(Class<?> owner, String resource) throws IOException {
        ModelFormat format = formatOf(resource);
        try (InputStream in = owner.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IOException("model '" + resource + "' not found among the resources of "
                        + owner.getName() + " (looked for " + resolved(owner, resource) + ")");
            }
            byte[] data = in.readAllBytes();
            if (data.length > ModelSpec.MAX_MODEL_BYTES) {
                throw new IOException("model '" + resource + "' has " + data.length + " bytes, at most "
                        + ModelSpec.MAX_MODEL_BYTES + " may be sent");
            }
            String source = resource.substring(resource.lastIndexOf('/') + 1);
            byte[] zip = format == ModelFormat.GLTF ? ModelFolder.zipped(owner, resource, data) : null;
            return zip == null ? new AgentModel(format, data, source) : new AgentModel(ModelFormat.ZIP, zip, source);
        }
    }

    /** A model from bytes in memory; {@code source} names it in messages. */
    public static AgentModel of(ModelFormat format, byte[] bytes, String source) {
        Objects.requireNonNull(format, "format");
        if (format == ModelFormat.BUNDLED) {
            throw new IllegalArgumentException("a bundled model is named, not sent: use ModelSpec.bundled");
        }
        return new AgentModel(format, bytes.clone(), source);
    }

    /**
     * The format a file name's extension stands for: {@code .x3d}, {@code .wrl}, {@code .gltf},
     * {@code .glb}.
     *
     * @throws IllegalArgumentException naming the extension and those known
     */
    public static ModelFormat formatOf(String fileName) {
        String lower = fileName.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".x3d")) {
            return ModelFormat.X3D;
        } else if (lower.endsWith(".wrl")) {
            return ModelFormat.VRML97;
        } else if (lower.endsWith(".gltf")) {
            return ModelFormat.GLTF;
        } else if (lower.endsWith(".glb")) {
            return ModelFormat.GLB;
        }
        throw new IllegalArgumentException("model '" + fileName + "' has an unknown extension; expected .x3d (X3D),"
                + " .wrl (VRML97), .gltf or .glb (glTF 2.0)");
    }

    /** The model's format: {@link ModelFormat#ZIP} for a model sent with its files. */
    public ModelFormat format() {
        return format;
    }

    /** The model's bytes (a copy). */
    public byte[] bytes() {
        return bytes.clone();
    }

    /** The model's file name, for messages. */
    public String source() {
        return source;
    }

    /** The model as registration sends it. */
    public ModelSpec spec() {
        return ModelSpec.of(format, bytes);
    }

    /**
     * The named nodes found: DEF name to node type for X3D and VRML97 ({@code "Transform"},
     * {@code "TimeSensor"}...); for glTF every name (of nodes, animations...) maps to "named".
     */
    public Map<String, String> nodes() {
        return nodes;
    }

    /**
     * What keeps the model from being registered for this agent; empty when nothing does.
     *
     * @param agent       the agent's name: the model must have a Transform of that name
     * @param joints      the joints the agent registers: each must be a node of the model
     * @param timeSensors the time sensors the agent registers: each must be a TimeSensor of the model
     *                    (for glTF, an animation's name)
     */
    public List<String> problems(String agent, Collection<String> joints, Collection<String> timeSensors) {
        List<String> problems = new ArrayList<>();
        boolean gltf = modelFormat == ModelFormat.GLTF || modelFormat == ModelFormat.GLB;
        String root = nodes.get(agent);
        if (root == null) {
            problems.add("no Transform named after the agent: the model has no node " + def(agent));
        } else if (!gltf && !root.equals("Transform")) {
            problems.add("the node " + def(agent) + " is a " + root + ", expected a Transform");
        }
        for (String joint : joints) {
            String type = nodes.get(joint);
            if (type == null) {
                problems.add("no joint " + joint + ": the model has no node " + def(joint));
            } else if (!gltf && !JOINT_TYPES.contains(type)) {
                problems.add("joint " + joint + " is a " + type + ", expected a Transform");
            }
        }
        for (String sensor : timeSensors) {
            String type = nodes.get(sensor);
            if (type == null) {
                problems.add("no time sensor " + sensor + ": the model has no " + (gltf ? "animation named '"
                        + sensor + "'" : "node " + def(sensor)));
            } else if (!gltf && !type.equals("TimeSensor")) {
                problems.add("time sensor " + sensor + " is a " + type + ", expected a TimeSensor");
            }
        }
        return problems;
    }

    /**
     * Checks the model for this agent.
     *
     * @throws ModelCheckException listing everything missing
     */
    public void check(String agent, Collection<String> joints, Collection<String> timeSensors) {
        List<String> problems = problems(agent, joints, timeSensors);
        if (!problems.isEmpty()) {
            throw new ModelCheckException(source, problems);
        }
    }

    /**
     * The same model with every node whose name starts with {@code from} renamed to start with
     * {@code to} instead (the root Transform, its mover and its time sensors), where nodes are
     * defined, used and routed. The model of "Dwarf" becomes the model of "Dwarf2".
     */
    public AgentModel renamed(String from, String to) {
        Checks.name(from, "from");
        Checks.name(to, "to");
        if (from.equals(to)) {
            return this;
        }
        String text = new String(bytes, StandardCharsets.UTF_8);
        String name = Pattern.quote(from);
        String out;
        if (format == ModelFormat.X3D) {
            out = text.replaceAll("(\\b(?:DEF|USE|fromNode|toNode)\\s*=\\s*[\"'])" + name + "([\\w-]*[\"'])",
                    "$1" + Matcher.quoteReplacement(to) + "$2");
        } else if (format == ModelFormat.VRML97) {
            out = text.replaceAll("(\\b(?:DEF|USE|ROUTE|TO)\\s+)" + name + "(?=[\\w-]*[\\s.{])",
                    "$1" + Matcher.quoteReplacement(to));
        } else if (format == ModelFormat.GLTF) {
            out = text.replaceAll("(\"name\"\\s*:\\s*\")" + name + "([^\"]*\")", "$1" + Matcher.quoteReplacement(to) + "$2");
        } else {
            throw new IllegalArgumentException("a binary glTF model or a zip (" + source + ") cannot be renamed;"
                    + " name its root node after the agent");
        }
        return new AgentModel(format, out.getBytes(StandardCharsets.UTF_8), source);
    }

    private static String def(String name) {
        return "DEF '" + name + "'";
    }

    private static String resolved(Class<?> owner, String resource) {
        if (resource.startsWith("/")) {
            return resource;
        }
        String pkg = owner.getPackageName().replace('.', '/');
        return "/" + (pkg.isEmpty() ? "" : pkg + "/") + resource;
    }

    private static Map<String, String> scan(ModelFormat format, byte[] bytes) {
        Map<String, String> found = new LinkedHashMap<>();
        switch (format) {
            case X3D -> {
                Matcher m = X3D_NODE.matcher(new String(bytes, StandardCharsets.UTF_8));
                while (m.find()) {
                    found.putIfAbsent(m.group(3), m.group(1));
                }
            }
            case VRML97 -> {
                Matcher m = VRML_NODE.matcher(withoutComments(new String(bytes, StandardCharsets.UTF_8)));
                while (m.find()) {
                    found.putIfAbsent(m.group(1), m.group(2));
                }
            }
            case GLTF, GLB -> {
                String json = format == ModelFormat.GLB ? glbJson(bytes) : new String(bytes, StandardCharsets.UTF_8);
                Matcher m = GLTF_NAME.matcher(json);
                while (m.find()) {
                    found.putIfAbsent(m.group(1), GLTF_TYPE);
                }
                indexNames(json, found);
            }
            default -> throw new IllegalArgumentException("cannot scan a " + format.wireName() + " model");
        }
        return found;
    }

    /** The names viewers give unnamed glTF nodes and clips: {@code node#i}, {@code clip#i} by their index. */
    private static void indexNames(String json, Map<String, String> found) {
        JsonNode root;
        try {
            root = INDEX_READER.readTree(json);
        } catch (JacksonException e) {
            return; // the light check reads what it can; the viewer names what is wrong
        }
        for (String[] kind : new String[][] {{"nodes", "node#"}, {"animations", "clip#"}}) {
            JsonNode entries = root == null ? null : root.get(kind[0]);
            for (int i = 0; entries != null && entries.isArray() && i < entries.size(); i++) {
                JsonNode name = entries.get(i).get("name");
                if (name == null || !name.isString() || name.stringValue().isEmpty()) {
                    found.putIfAbsent(kind[1] + i, GLTF_TYPE);
                }
            }
        }
    }

    /** VRML text without its comments ('#' to the end of the line) and with its strings blanked out. */
    private static String withoutComments(String text) {
        StringBuilder out = new StringBuilder(text.length());
        boolean inString = false;
        boolean inComment = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (inComment) {
                if (c == '\n' || c == '\r') {
                    inComment = false;
                    out.append(c);
                }
            } else if (inString) {
                if (c == '\\' && i + 1 < text.length()) {
                    i++;
                    out.append("  ");
                } else if (c == '"') {
                    inString = false;
                    out.append(c);
                } else {
                    out.append(' ');
                }
            } else if (c == '"') {
                inString = true;
                out.append(c);
            } else if (c == '#') {
                inComment = true;
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }

    /** The JSON chunk of a binary glTF file, or "" when the file is not one. */
    private static String glbJson(byte[] bytes) {
        if (bytes.length < 20) {
            return "";
        }
        ByteBuffer buffer = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        if (buffer.getInt(0) != 0x46546C67 || buffer.getInt(16) != 0x4E4F534A) {
            return "";
        }
        int length = buffer.getInt(12);
        if (length < 0 || 20 + length > bytes.length) {
            return "";
        }
        return new String(bytes, 20, length, StandardCharsets.UTF_8);
    }
}
