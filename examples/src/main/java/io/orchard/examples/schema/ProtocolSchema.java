package io.orchard.examples.schema;

import com.fasterxml.classmate.ResolvedType;
import com.fasterxml.jackson.annotation.JsonFormat;
import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.annotation.JsonValue;
import com.github.victools.jsonschema.generator.CustomDefinition;
import com.github.victools.jsonschema.generator.FieldScope;
import com.github.victools.jsonschema.generator.MemberScope;
import com.github.victools.jsonschema.generator.MethodScope;
import com.github.victools.jsonschema.generator.Option;
import com.github.victools.jsonschema.generator.OptionPreset;
import com.github.victools.jsonschema.generator.SchemaBuilder;
import com.github.victools.jsonschema.generator.SchemaGenerationContext;
import com.github.victools.jsonschema.generator.SchemaGenerator;
import com.github.victools.jsonschema.generator.SchemaGeneratorConfig;
import com.github.victools.jsonschema.generator.SchemaGeneratorConfigBuilder;
import com.github.victools.jsonschema.generator.SchemaVersion;
import io.orchard.protocol.MessageTypes;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Nullable;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.RecordComponent;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.TreeMap;
import tools.jackson.core.util.DefaultIndenter;
import tools.jackson.core.util.DefaultPrettyPrinter;
import tools.jackson.core.util.Separators;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * The JSON Schema (draft 2020-12) of the Orchard protocol, generated from the message records so
 * that it cannot drift from the code. docs/protocol.schema.json holds a copy for readers and for
 * clients in other languages; {@code ./orchard protocol-schema} prints it.
 *
 * <p>The document is one {@code oneOf} with a branch per message type, in the order of
 * {@link MessageTypes#all()}. A branch is an object whose {@code type} property is the constant
 * type name and whose other properties are the record's components, in declaration order. The
 * records and enums that messages carry ({@code Vec3}, {@code Body}, {@code Sector}, ...) are
 * shared under {@code $defs}, sorted by name. The rules follow the codec:
 * <ul>
 *   <li>a component is required unless it is annotated {@link Nullable}, and then it may also be null;</li>
 *   <li>{@code int} and {@code long} are integers, {@code double} a number, a {@code List} an array;</li>
 *   <li>an enum is a string, one of its wire names (the value of its {@link JsonValue} method);</li>
 *   <li>a record written as an array ({@link JsonFormat} with {@code Shape.ARRAY}, the tuples of the
 *       lean form) is an array whose {@code prefixItems} are its components in declaration order (each
 *       titled with the component's name), all
 *       of them present, a {@link Nullable} one possibly null; elements after them are allowed, as
 *       decoders ignore them;</li>
 *   <li>a getter the codec writes besides the components (a public {@code isX()} or {@code getX()})
 *       is an optional, read-only property: decoders ignore it.</li>
 *   <li>each field carries the constraints docs/protocol.md states for it ({@link Constraints}): bounds,
 *       patterns, lengths, the bundled models' names.</li>
 * </ul>
 * Unknown properties are allowed, as decoders ignore fields they do not know. The output is the
 * same on every run and platform: pretty-printed with two spaces and ending with a newline.
 */
public final class ProtocolSchema {

    /** The JSON Schema dialect of the document. */
    public static final String DIALECT = "https://json-schema.org/draft/2020-12/schema";

    private static final String DEFINITIONS = "$defs";
    private static final String REFERENCE_PREFIX = "#/" + DEFINITIONS + "/";
    private static final String PROPERTIES = "properties";
    private static final String REQUIRED = "required";

    private static final JsonMapper MAPPER = JsonMapper.builder().build();
    private static final DefaultIndenter INDENTER = new DefaultIndenter("  ", "\n");
    private static final DefaultPrettyPrinter PRINTER = new DefaultPrettyPrinter(Separators.createDefaultInstance()
            .withObjectNameValueSpacing(Separators.Spacing.AFTER))
            .withObjectIndenter(INDENTER)
            .withArrayIndenter(INDENTER);

    private ProtocolSchema() {}

    /** The schema document as pretty-printed JSON, ending with a newline. */
    public static String json() {
        return MAPPER.writer().with(PRINTER).writeValueAsString(document()) + "\n";
    }

    private static ObjectNode document() {
        SchemaBuilder builder = new SchemaGenerator(config()).buildMultipleSchemaDefinitions();
        Map<String, ObjectNode> references = new LinkedHashMap<>();
        MessageTypes.all().forEach((name, type) -> references.put(name, builder.createSchemaReference(type)));
        ObjectNode generated = builder.collectDefinitions(DEFINITIONS);

        ObjectNode document = MAPPER.createObjectNode();
        document.put("$schema", DIALECT);
        document.put("title", "Orchard protocol " + ProtocolVersion.CURRENT);
        document.put("description", "One message of the Orchard protocol: a JSON object on one line, whose"
                + " \"type\" names the message type. Required fields must be present and not null, the others may"
                + " be left out or null; decoders ignore fields they do not know. Besides what this schema checks,"
                + " an integer is written without fraction or exponent (7, not 7.0 or 7e0), and a few rules"
                + " compare two fields or count UTF-16 code units: the descriptions state them.");
        ArrayNode oneOf = document.putArray("oneOf");
        Map<String, JsonNode> shared = new TreeMap<>();
        generated.properties().forEach(entry -> shared.put(entry.getKey(), entry.getValue()));
        references.forEach((name, reference) -> {
            String key = reference.get("$ref").asString().substring(REFERENCE_PREFIX.length());
            ObjectNode branch = message(name, MessageTypes.all().get(name), (ObjectNode) shared.remove(key));
            Constraints.apply(MessageTypes.all().get(name), branch);
            oneOf.add(branch);
        });
        Map<String, Class<?>> records = valueRecords();
        shared.forEach((key, definition) -> {
            Class<?> record = records.get(key);
            if (record != null) {
                Constraints.apply(record, (ObjectNode) definition);
            }
        });
        document.putObject(DEFINITIONS).setAll(shared);
        return document;
    }

    /** The records that messages carry, directly or in lists, by the name of their definition. */
    private static Map<String, Class<?>> valueRecords() {
        Map<String, Class<?>> found = new TreeMap<>();
        java.util.Deque<Class<?>> pending = new java.util.ArrayDeque<>(MessageTypes.all().values());
        while (!pending.isEmpty()) {
            for (RecordComponent component : pending.removeFirst().getRecordComponents()) {
                java.lang.reflect.Type generic = component.getGenericType();
                Class<?> type = generic instanceof java.lang.reflect.ParameterizedType list
                        && list.getActualTypeArguments()[0] instanceof Class<?> item ? item : component.getType();
                if (type.isRecord() && found.putIfAbsent(type.getSimpleName(), type) == null) {
                    pending.add(type);
                }
            }
        }
        return found;
    }

    /** A message's branch: its generated definition with the constant {@code type} in front. */
    private static ObjectNode message(String name, Class<? extends Message> type, ObjectNode generated) {
        ObjectNode branch = MAPPER.createObjectNode();
        branch.put("title", name);
        branch.put("description", direction(type));
        branch.put("type", "object");
        ObjectNode properties = branch.putObject(PROPERTIES);
        properties.putObject("type").put("const", name);
        properties.setAll((ObjectNode) generated.get(PROPERTIES));
        ArrayNode required = branch.putArray(REQUIRED).add("type");
        if (generated.has(REQUIRED)) {
            required.addAll((ArrayNode) generated.get(REQUIRED));
        }
        generated.properties().stream()
                .filter(entry -> !branch.has(entry.getKey()))
                .forEach(entry -> branch.set(entry.getKey(), entry.getValue()));
        return branch;
    }

    private static String direction(Class<? extends Message> type) {
        boolean fromClients = ClientMessage.class.isAssignableFrom(type);
        boolean fromServer = ServerMessage.class.isAssignableFrom(type);
        if (fromClients && fromServer) {
            return "Sent by clients and by the server.";
        }
        return fromClients ? "Sent by a client to the server." : "Sent by the server to clients.";
    }

    private static SchemaGeneratorConfig config() {
        SchemaGeneratorConfigBuilder builder = new SchemaGeneratorConfigBuilder(MAPPER, SchemaVersion.DRAFT_2020_12,
                OptionPreset.PLAIN_JSON)
                .with(Option.DEFINITIONS_FOR_ALL_OBJECTS, Option.PLAIN_DEFINITION_KEYS)
                // Methods are considered only for the getters the codec writes (see isWrittenGetter).
                .with(Option.NONSTATIC_NONVOID_NONGETTER_METHODS, Option.FIELDS_DERIVED_FROM_ARGUMENTFREE_METHODS)
                .without(Option.FLATTENED_ENUMS, Option.SCHEMA_VERSION_INDICATOR);
        builder.forTypesInGeneral()
                .withCustomDefinitionProvider(ProtocolSchema::enumOfWireNames)
                .withCustomDefinitionProvider(ProtocolSchema::tupleOfComponents)
                .withPropertySorter(Comparator.comparingInt(ProtocolSchema::position)
                        .thenComparing(MemberScope::getSchemaPropertyName));
        builder.forFields()
                .withRequiredCheck(field -> !component(field).isAnnotationPresent(Nullable.class));
        builder.forMethods()
                .withIgnoreCheck(method -> !isWrittenGetter(method))
                .withReadOnlyCheck(method -> true);
        return builder.build();
    }

    /** An enum as a string that is one of its wire names. */
    private static CustomDefinition enumOfWireNames(ResolvedType type, SchemaGenerationContext context) {
        Class<?> erased = type.getErasedType();
        if (!erased.isEnum()) {
            return null;
        }
        ObjectNode definition = context.getGeneratorConfig().createObjectNode().put("type", "string");
        ArrayNode values = definition.putArray("enum");
        for (Object constant : erased.getEnumConstants()) {
            values.add(wireName((Enum<?>) constant));
        }
        return new CustomDefinition(definition);
    }

    /** A record written as an array: its components, in order, as the array's first elements. */
    private static CustomDefinition tupleOfComponents(ResolvedType type, SchemaGenerationContext context) {
        Class<?> erased = type.getErasedType();
        JsonFormat format = erased.getAnnotation(JsonFormat.class);
        if (!erased.isRecord() || format == null || format.shape() != JsonFormat.Shape.ARRAY) {
            return null;
        }
        ObjectNode definition = context.getGeneratorConfig().createObjectNode().put("type", "array");
        ArrayNode items = definition.putArray("prefixItems");
        for (RecordComponent component : erased.getRecordComponents()) {
            // The reference is filled in when the definitions are collected: it is added as it is, titled.
            ObjectNode item = context.createDefinitionReference(context.getTypeContext().resolve(
                    component.getGenericType()));
            if (component.isAnnotationPresent(Nullable.class)) {
                ObjectNode nullable = context.getGeneratorConfig().createObjectNode();
                nullable.putArray("anyOf").add(item).add(context.getGeneratorConfig().createObjectNode()
                        .put("type", "null"));
                item = nullable;
            }
            items.add(item.put("title", component.getName()));
        }
        definition.put("minItems", erased.getRecordComponents().length);
        return new CustomDefinition(definition);
    }

    /** The name of an enum constant on the wire: what its {@link JsonValue} method returns, else its name. */
    static String wireName(Enum<?> constant) {
        for (Method method : constant.getDeclaringClass().getMethods()) {
            if (method.isAnnotationPresent(JsonValue.class) && method.getParameterCount() == 0) {
                try {
                    return String.valueOf(method.invoke(constant));
                } catch (IllegalAccessException | InvocationTargetException e) {
                    throw new IllegalStateException("cannot read the wire name of " + constant.getDeclaringClass()
                            .getName() + "." + constant.name() + " through " + method.getName() + "()", e);
                }
            }
        }
        return constant.name();
    }

    /** The record component behind a field; every type the protocol carries is a record or an enum. */
    private static RecordComponent component(FieldScope field) {
        Class<?> record = field.getDeclaringType().getErasedType();
        return Arrays.stream(record.getRecordComponents() == null ? new RecordComponent[0] : record.getRecordComponents())
                .filter(component -> component.getName().equals(field.getDeclaredName()))
                .findFirst()
                .orElseThrow(() -> new IllegalStateException("expected " + record.getName() + "." + field.getDeclaredName()
                        + " to be a record component; the protocol's types are records and enums"));
    }

    /** Where a property goes: record components in declaration order, then the written getters by name. */
    private static int position(MemberScope<?, ?> member) {
        if (member instanceof FieldScope field) {
            RecordComponent[] components = field.getDeclaringType().getErasedType().getRecordComponents();
            String name = component(field).getName();
            for (int i = 0; i < components.length; i++) {
                if (components[i].getName().equals(name)) {
                    return i;
                }
            }
        }
        return Integer.MAX_VALUE;
    }

    /**
     * Whether the codec writes what this method returns as a property: a public, argument-free
     * {@code getX()}, or {@code isX()} returning a boolean, that is not a record component's accessor,
     * not declared by {@code Object}, {@code Record} or {@code Enum} and not {@link JsonIgnore}d.
     */
    private static boolean isWrittenGetter(MethodScope method) {
        Method raw = method.getRawMember();
        Class<?> owner = raw.getDeclaringClass();
        String name = raw.getName();
        Class<?> returned = raw.getReturnType();
        boolean getter = name.length() > 3 && name.startsWith("get") && Character.isUpperCase(name.charAt(3))
                && returned != void.class;
        boolean isGetter = name.length() > 2 && name.startsWith("is") && Character.isUpperCase(name.charAt(2))
                && (returned == boolean.class || returned == Boolean.class);
        boolean accessor = owner.isRecord() && Arrays.stream(owner.getRecordComponents())
                .anyMatch(component -> component.getName().equals(name));
        return (getter || isGetter) && !accessor
                && Modifier.isPublic(raw.getModifiers()) && !Modifier.isStatic(raw.getModifiers())
                && raw.getParameterCount() == 0
                && owner != Object.class && owner != Record.class && owner != Enum.class
                && !raw.isAnnotationPresent(JsonIgnore.class);
    }
}
