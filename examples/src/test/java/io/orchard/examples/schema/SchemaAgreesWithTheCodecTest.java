package io.orchard.examples.schema;

import static org.assertj.core.api.Assertions.assertThat;

import com.networknt.schema.InputFormat;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.MessageTypes;
import io.orchard.protocol.ProtocolException;
import io.orchard.protocol.message.ClientMessage;
import java.io.IOException;
import java.math.BigInteger;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.JsonNodeFactory;
import tools.jackson.databind.node.ObjectNode;

/**
 * docs/protocol.schema.json, read by a JSON Schema validator as a client in another language would
 * read it, takes what the codec takes and refuses what it refuses: the golden lines, the bad
 * examples of docs/protocol.md, and every golden line with one field changed to a value out of a
 * table of likely mistakes. Where JSON Schema cannot say a rule (two fields compared, an integer
 * written 7.0), the schema's descriptions say it instead.
 */
class SchemaAgreesWithTheCodecTest {

    private static final Path SCHEMA = Path.of("docs", "protocol.schema.json");
    private static final Path GOLDEN = Path.of("protocol", "src", "test", "resources", "golden");
    private static final JsonMapper MAPPER = JsonMapper.builder().build();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    private static final MessageCodec CODEC = new MessageCodec();

    /** What the codec says when two fields disagree, which the schema can only describe. */
    private static final List<String> BETWEEN_FIELDS = List.of("minX < maxX", "must not be below minHeight",
            "two different entry points");

    private static Path root;
    private static Schema schema;
    private static JsonNode document;

    @BeforeAll
    static void load() throws IOException {
        root = ProtocolSchemaTest.repositoryRoot();
        String text = Files.readString(root.resolve(SCHEMA), StandardCharsets.UTF_8);
        document = MAPPER.readTree(text);
        schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(text, InputFormat.JSON);
    }

    private static boolean schemaTakes(String line) {
        return schema.validate(line, InputFormat.JSON).isEmpty();
    }

    /** The codec's verdict as the receiving side has it: null when it takes the line, else its refusal. */
    private static ProtocolException codecRefusal(String line) {
        try {
            String type = MAPPER.readTree(line).path("type").asString("");
            Class<?> record = MessageTypes.all().get(type);
            if (record != null && ClientMessage.class.isAssignableFrom(record)) {
                CODEC.decodeClient(line);
            } else {
                CODEC.decodeServer(line);
            }
            return null;
        } catch (ProtocolException refused) {
            return refused;
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("goldenLines")
    void everyGoldenLineIsValid(String type, String line) {
        assertThat(schema.validate(line, InputFormat.JSON)).as("golden/%s.json", type).isEmpty();
    }

    /** The lines, and the examples of docs/protocol.md section 2.7 that are JSON at all. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', textBlock = """
        seq -1                    | {"type":"EndTurn","seq":-1,"tick":2}
        a name with a space       | {"type":"Unregister","seq":1,"agent":"no spaces"}
        radius -1                 | {"type":"Register","seq":2,"name":"G","body":{"radius":-1,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}}}
        fieldOfView 99            | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":99}}}
        bearing 10                | {"type":"LandmarkPerception","tick":1,"agent":"G","bridges":[{"id":"B1","entryA":{"distance":1,"bearing":10},"entryB":{"distance":2,"bearing":0},"width":4}]}
        bundled with no name      | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"bundled"}}
        bundled no_such_model     | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"bundled","bundled":"no_such_model"}}
        data with a bundled name  | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"glb","bundled":"bunny","data":"QUJD"}}
        data not Base64           | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"glb","data":"QUJD!"}}
        no type                   | {"seq":1,"tick":2}
        unknown type              | {"type":"Teleport","seq":1}
        missing field             | {"type":"EndTurn","seq":1}
        null for a string         | {"type":"Move","seq":6,"agent":null,"from":{"x":1,"y":0,"z":2},"to":{"x":1,"y":0,"z":2}}
        null for a number         | {"type":"EndTurn","seq":1,"tick":null}
        string for a number       | {"type":"EndTurn","seq":1,"tick":"7"}
        number for a string       | {"type":"Say","seq":1,"agent":"Guppy","text":12}
        fraction for an integer   | {"type":"EndTurn","seq":1,"tick":7.5}
        integer out of range      | {"type":"EndTurn","seq":1,"tick":123456789012345678901234567890}
        seq of two to the 63      | {"type":"EndTurn","seq":9223372036854775808,"tick":2}
        int32 out of range        | {"type":"PerceptionRequest","seq":1,"agent":"A","every":4294967296}
        number beyond a double    | {"type":"Tick","tick":1,"time":1e999}
        negative time             | {"type":"Tick","tick":1,"time":-3}
        unknown enum value        | {"type":"GameControl","seq":1,"command":"explode"}
        enum in the wrong case    | {"type":"Hello","seq":1,"protocolVersion":2,"role":"Agent","client":"c"}
        protocol version 0        | {"type":"Hello","seq":1,"protocolVersion":0,"role":"agent","client":"c"}
        null array element        | {"type":"ScoreUpdate","tick":1,"scores":[null]}
        the zero axis             | {"type":"SetRotation","seq":1,"agent":"G","rotation":{"axis":{"x":0,"y":0.0,"z":0},"angle":1}}
        an unknown sector         | {"type":"CastlePerception","tick":1,"agent":"G","sector":"north-by-north"}
        an empty id               | {"type":"GraspRequest","seq":1,"agent":"G","fruit":""}
        an id of white space      | {"type":"GraspRequest","seq":1,"agent":"G","fruit":"   "}
        a text of 1001 characters | {"type":"Say","seq":1,"agent":"G","text":"%1001"}
        """)
    void theSpecsBadExamplesAreInvalid(String name, String line) {
        String expanded = line.replace("%1001", "a".repeat(1001));
        assertThat(codecRefusal(expanded)).as("the codec refuses %s", expanded).isNotNull();
        assertThat(schemaTakes(expanded)).as("the schema refuses %s", expanded).isFalse();
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        a null model              | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":null}
        a move without from       | {"type":"Move","seq":6,"agent":"Guppy","to":{"x":1,"y":0,"z":2}}
        a move with a null from   | {"type":"Move","seq":6,"agent":"Guppy","from":null,"to":{"x":1,"y":0,"z":2}}
        unpadded Base64           | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"glb","data":"QUI"}}
        a null bundled with data  | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"glb","bundled":null,"data":"QUJD"}}
        a bearing of pi           | {"type":"LandmarkPerception","tick":1,"agent":"G","bridges":[{"id":"B1","entryA":{"distance":1,"bearing":3.141592653589793},"entryB":{"distance":2,"bearing":-3.14159},"width":4}]}
        a GameStarted without seed | {"type":"GameStarted","tick":0,"fruitCount":30,"timeLimit":180.0}
        a Welcome of version 1    | {"type":"Welcome","seq":1,"protocolVersion":1,"serverVersion":"0.1.0","role":"agent","bounds":{"minX":-1,"minZ":-1,"maxX":1,"maxZ":1},"tickRate":20,"clock":"lockstep","tick":0}
        a field of a later version | {"type":"EndTurn","seq":1,"tick":2,"hurry":true}
        the largest seq           | {"type":"EndTurn","seq":9223372036854775807,"tick":0}
        """)
    void whatTheSpecAllowsIsValid(String name, String line) {
        assertThat(codecRefusal(line)).as("the codec takes %s", line).isNull();
        assertThat(schema.validate(line, InputFormat.JSON)).as("the schema takes %s", line).isEmpty();
    }

    @Test
    void whatJsonSchemaCannotSayIsSaidInTheDescriptions() {
        for (String line : List.of("{\"type\":\"EndTurn\",\"seq\":1,\"tick\":7.0}", "{\"type\":\"EndTurn\",\"seq\":1,\"tick\":1e2}")) {
            assertThat(codecRefusal(line)).isNotNull();
        }
        assertThat(document.get("description").asString()).contains("without fraction or exponent (7, not 7.0 or 7e0)");
        assertThat(document.at("/$defs/Bounds/description").asString()).contains("minX < maxX and minZ < maxZ");
        assertThat(document.at("/$defs/Gripper/description").asString()).contains("maxHeight >= minHeight");
        assertThat(document.at("/$defs/BridgeShape/description").asString()).contains("entryB is not the same point");
        assertThat(document.at("/$defs/ModelSpec/properties/data/description").asString())
                .contains("at most 4194304 bytes once decoded");
    }

    /**
     * Every golden line with one field changed, or left out: the schema and the codec give the same
     * verdict, except where two fields are compared, which the schema cannot check and describes.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("goldenLines")
    void aGoldenLineWithOneFieldChangedIsValidForTheSchemaExactlyWhenTheCodecTakesIt(String type, String line) {
        ObjectNode message = (ObjectNode) MAPPER.readTree(line);
        List<String> disagreements = new ArrayList<>();
        int tried = 0;
        for (Mutation mutation : mutations(message, message, "")) {
            String changed = MAPPER.writeValueAsString(mutation.apply(message));
            ProtocolException refusal = codecRefusal(changed);
            boolean schemaValid = schemaTakes(changed);
            tried++;
            if ((refusal == null) != schemaValid && !(schemaValid && refusal != null
                    && BETWEEN_FIELDS.stream().anyMatch(refusal.getMessage()::contains))) {
                disagreements.add(mutation.what() + ": codec " + (refusal == null ? "takes it" : "refuses it ("
                        + refusal.getMessage() + ")") + ", schema " + (schemaValid ? "takes it" : "refuses it"));
            }
        }
        assertThat(tried).isPositive();
        assertThat(disagreements).as("changes to golden/%s.json", type).isEmpty();
    }

    private record Mutation(String what, String path, JsonNode value) {

        ObjectNode apply(ObjectNode message) {
            ObjectNode copy = message.deepCopy();
            String[] parts = path.substring(1).split("/");
            JsonNode parent = copy;
            for (int i = 0; i < parts.length - 1; i++) {
                parent = parent.isArray() ? parent.get(Integer.parseInt(parts[i])) : parent.get(parts[i]);
            }
            String last = parts[parts.length - 1];
            if (parent instanceof ObjectNode object) {
                if (value == null) {
                    object.remove(last);
                } else {
                    object.set(last, value);
                }
            } else if (value == null) {
                ((ArrayNode) parent).remove(Integer.parseInt(last));
            } else {
                ((ArrayNode) parent).set(Integer.parseInt(last), value);
            }
            return copy;
        }
    }

    /** For every field below {@code node}: leaving it out, null, and a table of values of every JSON kind. */
    private static List<Mutation> mutations(ObjectNode message, JsonNode node, String path) {
        List<Mutation> found = new ArrayList<>();
        if (node.isObject()) {
            for (Map.Entry<String, JsonNode> field : node.properties()) {
                String at = path + "/" + field.getKey();
                if (at.equals("/type")) {
                    continue;
                }
                found.add(new Mutation(at + " left out", at, null));
                found.addAll(values(at, field.getValue()));
                found.addAll(mutations(message, field.getValue(), at));
            }
        } else if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                String at = path + "/" + i;
                found.addAll(values(at, node.get(i)));
                found.addAll(mutations(message, node.get(i), at));
            }
            found.add(new Mutation(path + " emptied", path, NODES.arrayNode()));
        }
        return found;
    }

    private static List<Mutation> values(String at, JsonNode was) {
        List<JsonNode> values = new ArrayList<>(List.of(NODES.nullNode(), NODES.booleanNode(true), NODES.objectNode(),
                NODES.arrayNode(), NODES.stringNode("7")));
        if (was.isIntegralNumber()) {
            for (long value : new long[] {-1, 0, 1, 7, Integer.MAX_VALUE + 1L, Long.MAX_VALUE}) {
                values.add(NODES.numberNode(value));
            }
            values.add(NODES.numberNode(new BigInteger("9223372036854775808")));
            values.add(NODES.numberNode(7.5));
        } else if (was.isNumber()) {
            for (double value : new double[] {-4, -1, 0, 1e-9, 0.5, 3.2, 6.3, 7, 10, 99, -Math.PI, Math.PI}) {
                values.add(NODES.numberNode(value));
            }
        } else if (was.isString()) {
            for (String value : List.of("", " ", "no spaces", "Z", "9lives", "a_b-c", "figure", "bunny", "dragon",
                    "x".repeat(32), "x".repeat(33), "x".repeat(64), "x".repeat(65), "x".repeat(1000), "x".repeat(1001),
                    "tab\there", "QUJD", "QUI", "QQ", "Q", "QUJD!", "agent", "viewer", "north", "banana", "bundled",
                    "x3d", "start")) {
                values.add(NODES.stringNode(value));
            }
            values.add(NODES.numberNode(12));
        } else if (was.isBoolean()) {
            values.add(NODES.booleanNode(false));
            values.add(NODES.numberNode(1));
        }
        return values.stream().map(value -> new Mutation(at + " = " + shown(value), at, value)).toList();
    }

    private static String shown(JsonNode value) {
        String text = value.toString();
        return text.length() > 30 ? text.substring(0, 30) + "..." : text;
    }

    static Stream<Arguments> goldenLines() throws IOException {
        Path directory = ProtocolSchemaTest.repositoryRoot().resolve(GOLDEN);
        List<Arguments> lines = new ArrayList<>();
        try (Stream<Path> files = Files.list(directory)) {
            for (Path file : files.filter(path -> path.toString().endsWith(".json")).sorted().toList()) {
                String type = file.getFileName().toString().replace(".json", "");
                lines.add(Arguments.of(type, Files.readString(file, StandardCharsets.UTF_8).strip()));
            }
        }
        assertThat(lines).as("golden lines in %s", directory).isNotEmpty();
        return lines.stream();
    }
}
