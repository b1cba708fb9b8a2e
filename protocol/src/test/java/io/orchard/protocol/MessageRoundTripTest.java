package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.ServerMessage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class MessageRoundTripTest {

    /** Set -Dorchard.golden.update=true to rewrite the golden lines after a deliberate format change. */
    private static final boolean UPDATE = Boolean.getBoolean("orchard.golden.update");
    private static final Path GOLDEN = Paths.get("src/test/resources/golden");

    private final MessageCodec codec = new MessageCodec();

    static java.util.stream.Stream<String> types() {
        return Samples.types();
    }

    @Test
    void everyMessageOfThePaperIsAType() {
        assertThat(MessageTypes.names()).contains(
                "Register", "RegisterJoint", "RegisterTimeSensor", "Unregister", "Move", "SetRotation",
                "SetJointRotation", "StartAnimation", "StopAnimation", "GraspRequest", "PerceptionRequest",
                "Perception", "LandmarkPerception", "CastlePerception", "FruitEaten");
    }

    @Test
    void everyTypeHasExactlyOneSample() {
        assertThat(Samples.count()).isEqualTo(MessageTypes.names().size());
        types().forEach(Samples::of);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("types")
    void roundTripGivesAnEqualRecord(String type) {
        Message sample = Samples.of(type);
        String line = codec.encode(sample);
        assertThat(line).doesNotContain("\n").startsWith("{\"type\":\"" + type + "\"");
        assertThat(codec.decode(line)).isEqualTo(sample);
        assertThat(codec.decode(codec.encodeLine(sample))).isEqualTo(sample);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("types")
    void encodingMatchesTheGoldenLine(String type) throws IOException {
        Path file = GOLDEN.resolve(type + ".json");
        String line = codec.encode(Samples.of(type));
        if (UPDATE) {
            Files.createDirectories(GOLDEN);
            Files.writeString(file, line + "\n", StandardCharsets.UTF_8);
        }
        assertThat(file).as("golden line for %s (run with -Dorchard.golden.update=true after a deliberate change)", type)
                .exists();
        String golden = Files.readString(file, StandardCharsets.UTF_8).strip();
        assertThat(line).isEqualTo(golden);
        assertThat(codec.decode(golden)).isEqualTo(Samples.of(type));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("types")
    void directionDecodersAcceptOnlyTheirDirection(String type) {
        Message sample = Samples.of(type);
        String line = codec.encode(sample);
        if (sample instanceof ClientMessage) {
            assertThat(codec.decodeClient(line)).isEqualTo(sample);
        } else {
            assertThat(catchProtocol(() -> codec.decodeClient(line)).code().wireName()).isEqualTo("wrong_direction");
        }
        if (sample instanceof ServerMessage) {
            assertThat(codec.decodeServer(line)).isEqualTo(sample);
        } else {
            assertThat(catchProtocol(() -> codec.decodeServer(line)).code().wireName()).isEqualTo("wrong_direction");
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("types")
    void theWireCarriesExactlyTheRecordComponents(String type) throws Exception {
        Message sample = Samples.of(type);
        tools.jackson.databind.JsonNode line = tools.jackson.databind.json.JsonMapper.builder().build()
                .readTree(codec.encode(sample));
        assertThat(line.get("type").asString()).isEqualTo(type);
        assertComponents(sample, line, type);
    }

    /** Every field on the wire is a component of its record, so no accessor leaks onto the wire. */
    private static void assertComponents(Object value, tools.jackson.databind.JsonNode node, String path)
            throws Exception {
        if (value instanceof Record record) {
            java.util.Set<String> names = new java.util.HashSet<>();
            for (var component : record.getClass().getRecordComponents()) {
                names.add(component.getName());
                Object child = component.getAccessor().invoke(record);
                if (child != null) {
                    assertComponents(child, node.get(component.getName()), path + "." + component.getName());
                }
            }
            java.util.List<String> onWire = new java.util.ArrayList<>();
            node.propertyNames().forEach(onWire::add);
            onWire.remove("type");
            assertThat(names).as("fields of %s", path).containsAll(onWire);
        } else if (value instanceof java.util.List<?> list) {
            for (int i = 0; i < list.size(); i++) {
                assertComponents(list.get(i), node.get(i), path + "[" + i + "]");
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("types")
    void theSpecificationShowsTheGoldenLine(String type) throws IOException {
        String specification = Files.readString(Paths.get("../docs/protocol.md"), StandardCharsets.UTF_8);
        String golden = Files.readString(GOLDEN.resolve(type + ".json"), StandardCharsets.UTF_8).strip();
        assertThat(specification).as("docs/protocol.md shows the example line of %s", type).contains(golden);
    }

    @Test
    void goldenFilesHaveNoStrays() throws IOException {
        try (var files = Files.list(GOLDEN)) {
            assertThat(files.map(f -> f.getFileName().toString().replace(".json", "")))
                    .containsExactlyInAnyOrderElementsOf(MessageTypes.names());
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    static ProtocolException catchProtocol(Runnable decode) {
        try {
            decode.run();
        } catch (ProtocolException e) {
            return e;
        }
        throw new AssertionError("expected a ProtocolException");
    }
}
