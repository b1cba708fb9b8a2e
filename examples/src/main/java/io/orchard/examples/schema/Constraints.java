package io.orchard.examples.schema;

import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.LeanUnits;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Rotation;
import java.lang.reflect.RecordComponent;
import java.util.List;
import java.util.Map;
import java.util.Set;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * The constraints docs/protocol.md states for each field, written into the generated schema: the
 * spec's field types (int64, int32, number, name, id, text) and the bounds of its tables. The
 * records check the same in their constructors; a test holds the two together by feeding the
 * codec and the schema the same lines. A field is known by its name and Java type, as the
 * protocol uses a name for one thing throughout; a component this class does not know fails the
 * generation, so that a new field gets its constraints written down.
 *
 * <p>What JSON Schema cannot say is in the descriptions: a comparison between two fields, the form
 * of an integer literal ({@code 7.0} is an integer to JSON Schema), lengths counted in UTF-16 code
 * units, and a model's size once decoded.
 */
final class Constraints {

    private static final String NAME_PATTERN = "^" + Checks.NAME.pattern() + "$";
    private static final String PART_NAME_PATTERN = "^" + Checks.PART_NAME.pattern() + "$";
    /** 1 to 64 characters, none a control character, not all white space (as Java's isWhitespace has it). */
    private static final String ID_PATTERN = "^[^\\u0000-\\u001f\\u007f-\\u009f]*"
            + "[^\\u0000-\\u0020\\u007f-\\u009f\\u1680\\u2000-\\u2006\\u2008-\\u200a\\u2028\\u2029\\u205f\\u3000]"
            + "[^\\u0000-\\u001f\\u007f-\\u009f]*$";
    /** Base64 of the standard alphabet; the padding may be left out, as the server reads it. */
    private static final String BASE64_PATTERN =
            "^(?:[A-Za-z0-9+/]{4})*(?:[A-Za-z0-9+/]{2}(?:==)?|[A-Za-z0-9+/]{3}=?)?$";
    /** The bearing's range (-pi, pi] with the reader's slack of 1e-9 for rounding. */
    private static final double BEARING_SLACK = 1e-9;

    private static final Set<String> NAMES = Set.of("agent", "name", "part", "bundled");
    private static final Set<String> PART_NAMES = Set.of("joint", "timeSensor");
    private static final Set<String> IDS = Set.of("id", "fruit", "support");
    private static final Set<String> TEXTS = Set.of("text", "reason", "client", "token", "operatorToken",
            "resumeToken", "serverVersion", "action", "from");
    private static final Set<String> POSITIVE = Set.of("radius", "height", "maxSpeed", "reach", "range", "width");
    private static final Set<String> NON_NEGATIVE = Set.of("distance", "duration", "startTime", "time", "timeLimit",
            "minHeight");
    private static final Set<String> FINITE = Set.of("x", "y", "z", "heading", "angle", "across", "maxHeight", "minX",
            "minZ", "maxX", "maxZ");
    private static final Set<String> COUNTS = Set.of("every", "points", "fruit", "fruitCount");
    /** The lean form's whole numbers ({@code LeanUnits}): centimetres of 0 or more, of 1 or more, milliradians of a bearing, any. */
    private static final Set<String> LEAN_DISTANCES = Set.of("distance", "distanceA", "distanceB");
    private static final Set<String> LEAN_SIZES = Set.of("radius", "height", "width");
    private static final Set<String> LEAN_BEARINGS = Set.of("bearing", "bearingA", "bearingB");
    private static final Set<String> LEAN_ANY = Set.of("x", "y", "z", "heading", "across");
    private static final Set<String> POLYGONS = Set.of("footprint", "outline");
    private static final Map<Class<?>, String> BETWEEN_FIELDS = Map.of(
            Bounds.class, "minX < maxX and minZ < maxZ.",
            Gripper.class, "maxHeight >= minHeight.",
            BridgeShape.class, "entryB is not the same point as entryA.");

    private static final JsonMapper MAPPER = JsonMapper.builder().build();

    private Constraints() {}

    /** Writes the constraints of {@code record}'s components into its schema, {@code definition}. */
    static void apply(Class<?> record, ObjectNode definition) {
        if (definition.get("prefixItems") instanceof ArrayNode items) {
            tuple(record, items);
            return;
        }
        ObjectNode properties = (ObjectNode) definition.get("properties");
        for (RecordComponent component : record.getRecordComponents()) {
            ObjectNode property = (ObjectNode) properties.get(component.getName());
            constrain(record, component.getName(), component.getType(), property);
            if (component.isAnnotationPresent(Nullable.class)) {
                // An optional field may be null as well as absent.
                properties.set(component.getName(), orNull(property));
            }
        }
        if (record == Rotation.class) {
            definition.set("not", notTheZeroAxis());
        } else if (record == ModelSpec.class) {
            eitherBundledOrData(definition);
        } else if (record == GameControlMessage.class) {
            seedOnlyWithRestart(definition);
        }
        String between = BETWEEN_FIELDS.get(record);
        if (between != null) {
            definition.put("description", "Also, which this schema cannot check: " + between);
        }
    }

    /** A record written as an array (the lean form's tuples): its components are the array's first items. */
    private static void tuple(Class<?> record, ArrayNode items) {
        RecordComponent[] components = record.getRecordComponents();
        for (int i = 0; i < components.length; i++) {
            ObjectNode item = (ObjectNode) items.get(i);
            if (item.get("anyOf") instanceof ArrayNode either) {
                item = (ObjectNode) either.get(0); // a Nullable component: its value, or null
            }
            constrain(record, components[i].getName(), components[i].getType(), item);
        }
    }

    private static void constrain(Class<?> record, String name, Class<?> type, ObjectNode property) {
        if (type == String.class) {
            text(record, name, property);
        } else if (type == double.class || type == Double.class) {
            number(record, name, property);
        } else if (type == long.class || type == Long.class) {
            long minimum;
            if (name.equals("seq") || name.equals("tick")) {
                minimum = 0;
            } else if (name.equals("seed") || name.equals("heading")) {
                minimum = Long.MIN_VALUE;
            } else {
                throw unknown(record, name);
            }
            property.put("minimum", minimum).put("maximum", Long.MAX_VALUE);
        } else if (type == int.class || type == Integer.class) {
            int minimum;
            int maximum = Integer.MAX_VALUE;
            if (COUNTS.contains(name) || LEAN_DISTANCES.contains(name)) {
                minimum = 0;
            } else if (name.equals("protocolVersion") || name.equals("tickRate") || LEAN_SIZES.contains(name)) {
                minimum = 1;
            } else if (LEAN_BEARINGS.contains(name)) {
                minimum = 1 - (int) LeanUnits.PI_MILLIRADIANS;
                maximum = (int) LeanUnits.PI_MILLIRADIANS;
            } else if (LEAN_ANY.contains(name)) {
                minimum = Integer.MIN_VALUE;
            } else {
                throw unknown(record, name);
            }
            property.put("minimum", minimum).put("maximum", maximum);
        } else if (List.class.isAssignableFrom(type)) {
            if (POLYGONS.contains(name)) {
                property.put("minItems", 3);
            }
        }
    }

    private static void text(Class<?> record, String name, ObjectNode property) {
        if (record == ModelSpec.class && name.equals("data")) {
            property.put("maxLength", (ModelSpec.MAX_MODEL_BYTES + 2) / 3 * 4).put("pattern", BASE64_PATTERN)
                    .put("description", "The model file in Base64, at most " + ModelSpec.MAX_MODEL_BYTES
                            + " bytes once decoded; with format zip, a zip whose files also unpack to at most that"
                            + " and that the server checks further (docs/protocol.md, 6.2).");
        } else if (PART_NAMES.contains(name)) {
            property.put("pattern", PART_NAME_PATTERN);
        } else if (NAMES.contains(name)) {
            property.put("pattern", NAME_PATTERN);
            if (record == ModelSpec.class) {
                ArrayNode names = property.putArray("enum");
                ModelSpec.BUNDLED_NAMES.forEach(names::add);
            }
        } else if (IDS.contains(name)) {
            property.put("minLength", 1).put("maxLength", 64).put("pattern", ID_PATTERN)
                    .put("description", "An object id: at most 64 characters counted in UTF-16 code units.");
        } else if (TEXTS.contains(name)) {
            property.put("maxLength", Checks.MAX_TEXT).put("description", "Free text: at most " + Checks.MAX_TEXT
                    + " characters counted in UTF-16 code units (a character beyond U+FFFF counts twice).");
        } else {
            throw unknown(record, name);
        }
    }

    private static void number(Class<?> record, String name, ObjectNode property) {
        if (POSITIVE.contains(name)) {
            property.put("exclusiveMinimum", 0).put("maximum", Double.MAX_VALUE);
        } else if (NON_NEGATIVE.contains(name)) {
            property.put("minimum", 0).put("maximum", Double.MAX_VALUE);
        } else if (name.equals("fieldOfView")) {
            property.put("exclusiveMinimum", 0).put("maximum", 2 * Math.PI);
        } else if (name.equals("bearing")) {
            property.put("exclusiveMinimum", -Math.PI - BEARING_SLACK).put("maximum", Math.PI + BEARING_SLACK);
        } else if (FINITE.contains(name)) {
            property.put("minimum", -Double.MAX_VALUE).put("maximum", Double.MAX_VALUE);
        } else {
            throw unknown(record, name);
        }
    }

    /** The property, or null: a {@code $ref} becomes one of two, a typed value gets "null" among its types. */
    private static ObjectNode orNull(ObjectNode property) {
        JsonNode type = property.get("type");
        if (type != null && type.isString()) {
            property.putArray("type").add(type.asString()).add("null");
            if (property.get("enum") instanceof ArrayNode values) {
                values.addNull();
            }
            return property;
        }
        ObjectNode either = MAPPER.createObjectNode();
        either.putArray("anyOf").add(property).add(MAPPER.createObjectNode().put("type", "null"));
        return either;
    }

    /** A rotation about (0, 0, 0) is no rotation: an axis whose every component is 0 is refused. */
    private static ObjectNode notTheZeroAxis() {
        ObjectNode zero = MAPPER.createObjectNode();
        zero.putArray("required").add("axis");
        ObjectNode axis = zero.putObject("properties").putObject("axis");
        axis.putArray("required").add("x").add("y").add("z");
        ObjectNode components = axis.putObject("properties");
        for (String component : List.of("x", "y", "z")) {
            components.putObject(component).put("const", 0);
        }
        return zero;
    }

    /** A bundled model names one and carries no data; any other format carries data and names none. */
    private static void eitherBundledOrData(ObjectNode definition) {
        definition.putObject("if").putObject("properties").putObject("format").put("const",
                ModelFormat.BUNDLED.wireName());
        ObjectNode then = definition.putObject("then");
        then.putArray("required").add("bundled");
        ObjectNode thenProperties = then.putObject("properties");
        thenProperties.putObject("bundled").put("type", "string");
        thenProperties.putObject("data").put("type", "null");
        ObjectNode otherwise = definition.putObject("else");
        otherwise.putArray("required").add("data");
        ObjectNode elseProperties = otherwise.putObject("properties");
        elseProperties.putObject("bundled").put("type", "null");
        elseProperties.putObject("data").put("type", "string");
    }

    /** A seed goes with the command restart alone: with another command, it is absent or null. */
    private static void seedOnlyWithRestart(ObjectNode definition) {
        definition.putObject("if").putObject("properties").putObject("command").putObject("not").put("const",
                GameCommand.RESTART.wireName());
        definition.putObject("then").putObject("properties").putObject("seed").put("type", "null");
    }

    private static IllegalStateException unknown(Class<?> record, String name) {
        return new IllegalStateException("no constraint is written down for " + record.getSimpleName() + "." + name
                + ": add its rule from docs/protocol.md to " + Constraints.class.getSimpleName());
    }
}
