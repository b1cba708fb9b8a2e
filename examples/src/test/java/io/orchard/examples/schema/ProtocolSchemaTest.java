package io.orchard.examples.schema;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.MessageTypes;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.value.Nullable;
import java.io.IOException;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ObjectNode;

class ProtocolSchemaTest {

    private static final Path COMMITTED = Path.of("docs", "protocol.schema.json");
    private static final Path GOLDEN = Path.of("protocol", "src", "test", "resources", "golden");
    private static final JsonMapper MAPPER = JsonMapper.builder().build();

    private static Path root;
    private static String json;
    private static ObjectNode schema;

    @BeforeAll
    static void generate() {
        root = repositoryRoot();
        json = ProtocolSchema.json();
        schema = (ObjectNode) MAPPER.readTree(json);
    }

    @Test
    void committedSchemaEqualsTheGeneratedOne() throws IOException {
        Path file = root.resolve(COMMITTED);
        assertThat(file)
                .as("%s is missing; run ./orchard protocol-schema --out %s", COMMITTED, COMMITTED)
                .isRegularFile();
        String committed = Files.readString(file, StandardCharsets.UTF_8).replace("\r\n", "\n");
        assertThat(committed)
                .as("%s is out of date with the message records; run ./orchard protocol-schema --out %s"
                        + " and commit the result", COMMITTED, COMMITTED)
                .isEqualTo(json);
    }

    @Test
    void generationIsDeterministicAndEndsWithANewline() {
        assertThat(ProtocolSchema.json()).isEqualTo(json);
        assertThat(json).endsWith("}\n").doesNotContain("\r").startsWith("{\n  \"$schema\": ");
        assertThat(schema.get("$schema").asString()).isEqualTo(ProtocolSchema.DIALECT);
    }

    @Test
    void oneOfNamesEveryMessageTypeInRegistryOrder() {
        List<String> titles = new ArrayList<>();
        List<String> constants = new ArrayList<>();
        for (JsonNode branch : schema.get("oneOf")) {
            titles.add(branch.get("title").asString());
            constants.add(branch.at("/properties/type/const").asString());
        }
        assertThat(titles).containsExactlyElementsOf(MessageTypes.names());
        assertThat(constants).containsExactlyElementsOf(MessageTypes.names());
    }

    @Test
    void moveRequiresEveryFieldButFromWhichMayBeNull() {
        assertThat(strings(branch("Move").get("required"))).containsExactly("type", "seq", "agent", "to");
        assertThat(branch("Move").at("/properties/from/anyOf/0/$ref").asString()).isEqualTo("#/$defs/Vec3");
        assertThat(branch("Move").at("/properties/from/anyOf/1/type").asString()).isEqualTo("null");
        assertThat(branch("Move").at("/properties/to/$ref").asString()).isEqualTo("#/$defs/Vec3");
    }

    @Test
    void registerDoesNotRequireItsNullableModelWhichMayBeNull() {
        JsonNode register = branch("Register");
        assertThat(strings(register.get("required"))).containsExactly("type", "seq", "name", "body");
        assertThat(register.at("/properties/model/anyOf/0/$ref").asString()).isEqualTo("#/$defs/ModelSpec");
        assertThat(register.at("/properties/model/anyOf/1/type").asString()).isEqualTo("null");
    }

    @Test
    void theConstraintsOfTheSpecAreInTheSchema() {
        assertThat(branch("EndTurn").at("/properties/seq/minimum").asLong()).isZero();
        assertThat(branch("EndTurn").at("/properties/seq/maximum").asLong()).isEqualTo(Long.MAX_VALUE);
        assertThat(branch("Unregister").at("/properties/agent/pattern").asString())
                .isEqualTo("^[A-Za-z][A-Za-z0-9_-]{0,31}$");
        assertThat(schema.at("/$defs/Body/properties/radius/exclusiveMinimum").asDouble()).isZero();
        assertThat(schema.at("/$defs/Sight/properties/fieldOfView/maximum").asDouble()).isEqualTo(2 * Math.PI);
        assertThat(schema.at("/$defs/RelativePosition/properties/bearing/maximum").asDouble())
                .isEqualTo(Math.PI + 1e-9);
        JsonNode bundled = schema.at("/$defs/ModelSpec/properties/bundled/enum");
        assertThat(bundled).hasSize(3);
        assertThat(List.of(bundled.get(0).asString(), bundled.get(1).asString())).containsExactly("figure", "bunny");
        assertThat(bundled.get(2).isNull()).as("an optional name may be null").isTrue();
        assertThat(strings(schema.at("/$defs/ModelSpec/then/required"))).containsExactly("bundled");
        assertThat(schema.at("/$defs/CastleShape/properties/footprint/minItems").asInt()).isEqualTo(3);
        assertThat(branch("Say").at("/properties/text/maxLength").asInt()).isEqualTo(1000);
        assertThat(branch("GameStarted").at("/properties/seed/type")).hasSize(2);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("messageTypes")
    void requiredListsTheComponentsThatAreNotNullable(String type) {
        Class<? extends Message> record = MessageTypes.all().get(type);
        List<String> expected = new ArrayList<>(List.of("type"));
        List<String> properties = new ArrayList<>(List.of("type"));
        for (RecordComponent component : record.getRecordComponents()) {
            properties.add(component.getName());
            if (!component.isAnnotationPresent(Nullable.class)) {
                expected.add(component.getName());
            }
        }
        assertThat(strings(branch(type).get("required"))).containsExactlyElementsOf(expected);
        assertThat(branch(type).get("properties").propertyNames()).containsExactlyElementsOf(properties);
    }

    @Test
    void valueRecordsAreSharedDefinitions() {
        JsonNode definitions = schema.get("$defs");
        assertThat(List.copyOf(definitions.propertyNames())).contains("Vec3", "Body", "Rotation", "ModelSpec", "Score")
                .isSorted();
        assertThat(strings(definitions.at("/ModelSpec/required"))).containsExactly("format");
        assertThat(strings(definitions.at("/Vec3/required"))).containsExactly("x", "y", "z");
    }

    @Test
    void numbersIntegersAndListsHaveTheirJsonTypes() {
        assertThat(schema.at("/$defs/Vec3/properties/x/type").asString()).isEqualTo("number");
        assertThat(schema.at("/$defs/Score/properties/points/type").asString()).isEqualTo("integer");
        assertThat(branch("Tick").at("/properties/tick/type").asString()).isEqualTo("integer");
        assertThat(branch("GameOver").at("/properties/ranking/type").asString()).isEqualTo("array");
        assertThat(branch("GameOver").at("/properties/ranking/items/$ref").asString()).isEqualTo("#/$defs/Score");
        assertThat(branch("AnimationStarted").at("/properties/loop/type").asString()).isEqualTo("boolean");
    }

    @Test
    void enumsListTheirWireNames() {
        assertThat(strings(schema.at("/$defs/Sector/enum"))).contains("north-east", "south-west");
        assertThat(strings(schema.at("/$defs/Role/enum"))).containsExactly("agent", "viewer");
        assertThat(strings(schema.at("/$defs/ErrorCode/enum"))).contains("invalid_value", "unknown_type");
        assertThat(schema.at("/$defs/Sector/type").asString()).isEqualTo("string");
    }

    @Test
    void everyEnumHasTheNamesTheCodecWrites() {
        List<Class<?>> enums = reachableTypes().stream().filter(Class::isEnum).toList();
        assertThat(enums).isNotEmpty();
        for (Class<?> type : enums) {
            List<String> written = Arrays.stream(type.getEnumConstants())
                    .map(constant -> MAPPER.writeValueAsString(constant))
                    .map(quoted -> quoted.substring(1, quoted.length() - 1))
                    .toList();
            assertThat(strings(schema.at("/$defs/" + type.getSimpleName() + "/enum")))
                    .as("enum values of %s", type.getName())
                    .containsExactlyElementsOf(written);
        }
    }

    @Test
    void helperMethodsOfValuesAreNotProperties() {
        JsonNode rotation = schema.at("/$defs/Rotation");
        assertThat(rotation.get("properties").propertyNames()).containsExactly("axis", "angle");
        assertThat(strings(rotation.get("required"))).containsExactly("axis", "angle");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("goldenLines")
    void everyFieldOfTheGoldenLineIsInTheSchema(String type, String line) {
        JsonNode message = MAPPER.readTree(line);
        assertThat(message.get("type").asString()).isEqualTo(type);
        List<String> missing = new ArrayList<>();
        collectUndeclared(message, branch(type), type, missing);
        assertThat(missing).as("fields of golden/%s.json that the schema does not declare", type).isEmpty();
        for (JsonNode required : branch(type).get("required")) {
            assertThat(message.has(required.asString()))
                    .as("golden/%s.json has the required field %s", type, required.asString())
                    .isTrue();
        }
    }

    static Stream<String> messageTypes() {
        return MessageTypes.names().stream();
    }

    static Stream<Arguments> goldenLines() throws IOException {
        Path directory = repositoryRoot().resolve(GOLDEN);
        List<Arguments> lines = new ArrayList<>();
        try (Stream<Path> files = Files.list(directory)) {
            for (Path file : files.filter(path -> path.toString().endsWith(".json")).sorted().toList()) {
                String type = file.getFileName().toString().replace(".json", "");
                for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                    if (!line.isBlank()) {
                        lines.add(Arguments.of(type, line));
                    }
                }
            }
        }
        assertThat(lines).as("golden lines in %s", directory).isNotEmpty();
        return lines.stream();
    }

    /** Adds to {@code missing} the path of every field of {@code value} that {@code declared} does not declare. */
    private static void collectUndeclared(JsonNode value, JsonNode declared, String path, List<String> missing) {
        JsonNode definition = resolve(declared);
        if (value.isObject()) {
            for (Map.Entry<String, JsonNode> field : value.properties()) {
                JsonNode property = definition.path("properties").get(field.getKey());
                if (property == null) {
                    missing.add(path + "." + field.getKey());
                } else {
                    collectUndeclared(field.getValue(), property, path + "." + field.getKey(), missing);
                }
            }
        } else if (value.isArray()) {
            JsonNode prefix = definition.get("prefixItems");
            for (int i = 0; i < value.size(); i++) {
                JsonNode element = prefix != null && i < prefix.size() ? prefix.get(i) : definition.get("items");
                if (element == null) {
                    missing.add(path + "[" + i + "]");
                } else {
                    collectUndeclared(value.get(i), element, path + "[" + i + "]", missing);
                }
            }
        }
    }

    /** The definition a property stands for: through its {@code $ref}, and for an optional one through its first choice. */
    private static JsonNode resolve(JsonNode node) {
        JsonNode chosen = node.has("anyOf") ? node.get("anyOf").get(0) : node;
        return chosen.has("$ref") ? schema.at(chosen.get("$ref").asString().substring(1)) : chosen;
    }

    private static JsonNode branch(String type) {
        for (JsonNode branch : schema.get("oneOf")) {
            if (branch.at("/properties/type/const").asString().equals(type)) {
                return branch;
            }
        }
        throw new AssertionError("no oneOf branch has type " + type);
    }

    private static List<String> strings(JsonNode array) {
        assertThat(array.isArray()).as("%s is an array", array).isTrue();
        List<String> values = new ArrayList<>();
        array.forEach(value -> values.add(value.asString()));
        return values;
    }

    /** Every class the messages carry, directly or through records and lists. */
    private static Set<Class<?>> reachableTypes() {
        Set<Class<?>> seen = new LinkedHashSet<>();
        Deque<Class<?>> pending = new ArrayDeque<>(MessageTypes.all().values());
        while (!pending.isEmpty()) {
            Class<?> type = pending.removeFirst();
            if (!seen.add(type) || !type.isRecord()) {
                continue;
            }
            for (RecordComponent component : type.getRecordComponents()) {
                Type generic = component.getGenericType();
                if (generic instanceof ParameterizedType parameterized) {
                    Arrays.stream(parameterized.getActualTypeArguments())
                            .filter(Class.class::isInstance)
                            .forEach(argument -> pending.add((Class<?>) argument));
                } else {
                    pending.add(component.getType());
                }
            }
        }
        return seen;
    }

    /** The directory holding pom.xml and settings.gradle.kts or docs/: the working directory or one above it. */
    static Path repositoryRoot() {
        Path start = Path.of("").toAbsolutePath();
        for (Path dir = start; dir != null; dir = dir.getParent()) {
            if (Files.isRegularFile(dir.resolve("pom.xml"))
                    && (Files.isRegularFile(dir.resolve("settings.gradle.kts")) || Files.isDirectory(dir.resolve("docs")))) {
                return dir;
            }
        }
        throw new IllegalStateException(
                "expected pom.xml with settings.gradle.kts or docs/ in " + start + " or a directory above it");
    }
}
