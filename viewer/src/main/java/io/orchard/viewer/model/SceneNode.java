package io.orchard.viewer.model;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * One node of the format-neutral scene description both parsers produce: its type, DEF name and
 * the fields the file set. Unset fields read as their defaults. A {@code USE} is the very same
 * object in two places, so identity means "the same node".
 *
 * <p>Arrays returned by the getters are shared with the description and must not be modified.
 */
public final class SceneNode {

    private final String typeName;
    private final NodeType type;
    private final String location;
    private final Map<String, Object> fields = new LinkedHashMap<>();
    private String defName;
    private int weight = 1;
    private int height = 1;

    /** A node of type {@code typeName} read at {@code location}, with no fields set yet. */
    public SceneNode(String typeName, String location) {
        this.typeName = typeName;
        this.type = NodeSchema.find(typeName).orElse(null);
        this.location = location;
    }

    /** The type name as written, such as {@code "Transform"}. */
    public String typeName() {
        return typeName;
    }

    /** The schema type, or empty for a node type this loader parses but does not build. */
    public Optional<NodeType> type() {
        return Optional.ofNullable(type);
    }

    /** Whether the loader knows the node's type, that is, can build it. */
    public boolean isKnown() {
        return type != null;
    }

    /** Whether the node is of type {@code name}. */
    public boolean is(String name) {
        return typeName.equals(name);
    }

    /** The DEF name, or empty if the node has none. */
    public Optional<String> defName() {
        return Optional.ofNullable(defName);
    }

    /** Sets the DEF name. */
    public void setDefName(String name) {
        this.defName = name;
    }

    /** Where the node starts in its file, such as {@code "line 4:3"}. */
    public String location() {
        return location;
    }

    /**
     * How many nodes this node stands for, itself and everything below it, counting each
     * {@code USE} in full: what instantiating it costs.
     */
    int weight() {
        return weight;
    }

    /** How many levels deep the tree below this node goes, itself included. */
    int height() {
        return height;
    }

    /**
     * Computes {@link #weight()} and {@link #height()} from the node's children, counting every
     * {@code USE} in full; called once, when the node's last child has been read.
     */
    public void complete() {
        int totalWeight = 1;
        int maxHeight = 0;
        for (SceneNode child : childNodes()) {
            totalWeight += child.weight;
            maxHeight = Math.max(maxHeight, child.height);
        }
        this.weight = totalWeight;
        this.height = maxHeight + 1;
    }

    /** Sets a field to a value in the representation {@link FieldType} describes. */
    public void set(String field, Object value) {
        fields.put(field, value);
    }

    /** Whether the file set the field (a default does not count). */
    public boolean has(String field) {
        return fields.containsKey(field);
    }

    /** The nodes held in node-valued fields, in file order (unknown types' fields included). */
    public List<SceneNode> childNodes() {
        List<SceneNode> result = new ArrayList<>();
        for (Object value : fields.values()) {
            if (value instanceof SceneNode node) {
                result.add(node);
            } else if (value instanceof List<?> list) {
                for (Object item : list) {
                    if (item instanceof SceneNode node) {
                        result.add(node);
                    }
                }
            }
        }
        return result;
    }

    /** The field's value, or its default if the file did not set it; null for an unset field of an unknown type. */
    public Object get(String field) {
        Object value = fields.get(field);
        if (value != null || fields.containsKey(field)) {
            return value;
        }
        if (type == null) {
            return null;
        }
        FieldDef def = type.fields().get(field);
        if (def == null) {
            throw new IllegalArgumentException(typeName + " has no field " + field);
        }
        return def.defaultValue();
    }

    /** The value of an SFBool field. */
    public boolean bool(String field) {
        return (Boolean) get(field);
    }

    /** The value of an SFInt32 field. */
    public int integer(String field) {
        return (Integer) get(field);
    }

    /** The value of an SFFloat or SFTime field. */
    public double number(String field) {
        return (Double) get(field);
    }

    /** The numbers of a vector, colour or rotation field, or of a numeric MF field but MFInt32, flat. */
    public float[] floats(String field) {
        return (float[]) get(field);
    }

    /** The numbers of an MFInt32 field. */
    public int[] ints(String field) {
        return (int[]) get(field);
    }

    /** The values of an MFString field. */
    @SuppressWarnings("unchecked")
    public List<String> strings(String field) {
        return (List<String>) get(field);
    }

    /** The node in an SFNode field, or null if it holds none. */
    public SceneNode node(String field) {
        return (SceneNode) get(field);
    }

    /**
     * The node in a node field if it is of type {@code typeName}, else null: a field that holds
     * a node type this loader does not build counts as empty.
     */
    public SceneNode node(String field, String typeName) {
        SceneNode node = node(field);
        return node != null && node.is(typeName) ? node : null;
    }

    /** The nodes in an MFNode field; empty if the field is unset and the type unknown. */
    @SuppressWarnings("unchecked")
    public List<SceneNode> nodes(String field) {
        Object value = get(field);
        return value == null ? List.of() : (List<SceneNode>) value;
    }

    /** How messages name this node: {@code Transform 'LeftKnee'} or {@code Shape (line 7:5)}. */
    public String label() {
        return defName != null ? typeName + " '" + defName + "'" : typeName + " (" + location + ")";
    }

    @Override
    public String toString() {
        return label();
    }
}
