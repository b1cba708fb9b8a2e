package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class DecodeErrorsTest {

    private static final String MOVE_HEAD = "{\"type\":\"Move\",\"seq\":6,\"agent\":\"Guppy\",";
    private static final String TO = "\"to\":{\"x\":1,\"y\":0,\"z\":2}";

    private final MessageCodec codec = new MessageCodec();

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        not JSON at all                | hello there                                                   | malformed_json  | one JSON object
        truncated object               | {"type":"Move","seq":6                                        | malformed_json  | malformed JSON
        array instead of object        | [1,2,3]                                                       | malformed_json  | one JSON object
        number instead of object       | 42                                                            | malformed_json  | one JSON object
        two objects on one line        | {"type":"EndTurn","seq":1,"tick":2} {"type":"EndTurn","seq":1,"tick":2} | malformed_json | malformed JSON
        NaN literal                    | {"type":"Tick","tick":1,"time":NaN}                    | malformed_json  | malformed JSON
        no type                        | {"seq":1,"tick":2}                                            | missing_field   | missing field 'type'
        unknown type                   | {"type":"Teleport","seq":1}                                   | unknown_type    | unknown message type 'Teleport'
        missing top-level field        | {"type":"EndTurn","seq":1}                                    | missing_field   | missing field 'tick'
        missing nested number          | {"type":"Move","seq":6,"agent":"Guppy","from":{"x":1,"z":2},"to":{"x":1,"y":0,"z":2}} | missing_field | missing field 'from.y'
        explicit null object           | {"type":"Move","seq":6,"agent":null,"from":{"x":1,"y":0,"z":2},"to":{"x":1,"y":0,"z":2}} | missing_field | missing field 'agent'
        null for a number              | {"type":"EndTurn","seq":1,"tick":null}                        | invalid_value   | 'tick'
        string for a number            | {"type":"EndTurn","seq":1,"tick":"7"}                         | invalid_value   | 'tick'
        fraction for an integer        | {"type":"EndTurn","seq":1,"tick":7.5}                         | invalid_value   | 'tick'
        number for a string            | {"type":"Say","seq":1,"agent":"Guppy","text":12}              | invalid_value   | 'text'
        object for a number            | {"type":"EndTurn","seq":1,"tick":{"n":1}}                     | invalid_value   | 'tick'
        huge integer                   | {"type":"EndTurn","seq":1,"tick":123456789012345678901234567890} | invalid_value | 'tick'
        overflowing double             | {"type":"Tick","tick":1,"time":1e999}                         | invalid_value   | time must be a finite number, was Infinity
        negative size                  | {"type":"Tick","tick":1,"time":-3}                            | invalid_value   | time must not be negative, was -3.0
        negative seq                   | {"type":"EndTurn","seq":-1,"tick":2}                          | invalid_value   | seq must not be negative, was -1
        unknown enum value             | {"type":"GameControl","seq":1,"command":"explode"}            | invalid_value   | 'command'
        bad agent name                 | {"type":"Unregister","seq":1,"agent":"no spaces"}             | invalid_value   | agent must be a letter
        duplicate key                  | {"type":"EndTurn","seq":1,"seq":2,"tick":2}                   | malformed_json  | Duplicate Object property
        empty line                     | ''                                                            | malformed_json  | empty line
        message of the other direction | {"type":"Tick","tick":1,"time":0}                             | wrong_direction | sent by the server
        """)
    void badLinesAreRefusedNamingTheProblem(String name, String line, String code, String fragment) {
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining(fragment)
                .extracting(e -> ((ProtocolException) e).code().wireName()).isEqualTo(code);
    }

    @Test
    void nonFiniteNestedCoordinateNamesItsPath() {
        String line = MOVE_HEAD + "\"from\":{\"x\":1e400,\"y\":0,\"z\":2}," + TO + "}";
        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessage("from.x must be a finite number, was Infinity");
    }

    @Test
    void unknownFieldsAreIgnoredForForwardCompatibility() {
        String line = MOVE_HEAD + "\"from\":{\"x\":1,\"y\":0,\"z\":2,\"w\":9},\"speedHint\":3," + TO + "}";
        assertThat(codec.decode(line)).isInstanceOf(MoveMessage.class);
    }

    @Test
    void optionalFieldsMayBeLeftOut() {
        RegisterMessage register = (RegisterMessage) codec.decode(
                "{\"type\":\"Register\",\"seq\":2,\"name\":\"Guppy\",\"body\":{\"radius\":0.5,\"height\":1.2,"
                        + "\"maxSpeed\":8,\"gripper\":{\"part\":\"hands\",\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},"
                        + "\"sight\":{\"range\":30,\"fieldOfView\":3.14}}}");
        assertThat(register.model()).isNull();
    }

    @Test
    void ordinaryLineLongerThan64KiBIsRefused() {
        String text = "a".repeat(900);
        StringBuilder line = new StringBuilder("{\"type\":\"Say\",\"seq\":1,\"agent\":\"Guppy\",\"text\":\"" + text + "\"");
        for (int i = 0; line.length() <= MessageCodec.MAX_LINE_BYTES; i++) {
            line.append(",\"pad").append(i).append("\":\"").append(text).append('"');
        }
        line.append('}');
        assertThatThrownBy(() -> codec.decode(line.toString()))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining("Say line of")
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.LINE_TOO_LONG);
    }

    @Test
    void messageCarryingAModelMayBeLongerThan64KiB() {
        byte[] model = new byte[1024 * 1024];
        new java.util.Random(7).nextBytes(model);
        RegisterMessage register = new RegisterMessage(2, "Guppy", Samples.BODY, ModelSpec.of(ModelFormat.GLB, model));
        byte[] line = codec.encodeLine(register);
        assertThat(line.length).isGreaterThan(MessageCodec.MAX_LINE_BYTES);
        RegisterMessage decoded = (RegisterMessage) codec.decode(line);
        assertThat(decoded.model().bytes()).isEqualTo(model);
    }

    @Test
    void lineBeyondTheLargeLimitIsRefusedBeforeParsing() {
        byte[] line = new byte[MessageCodec.MAX_LARGE_LINE_BYTES + 1];
        java.util.Arrays.fill(line, (byte) ' ');
        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(ProtocolException.class)
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.LINE_TOO_LONG);
    }

    @Test
    void invalidUtf8IsMalformed() {
        byte[] line = "{\"type\":\"Say\",\"seq\":1,\"agent\":\"Guppy\",\"text\":\"\u00ff\"}".getBytes(StandardCharsets.ISO_8859_1);
        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(ProtocolException.class)
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.MALFORMED_JSON);
    }

    @Test
    void nonAsciiTextSurvives() {
        SayMessage say = new SayMessage(1, "Guppy", "Grüße — ich habe die Banane 🍌");
        assertThat(codec.decode(codec.encodeLine(say))).isEqualTo(say);
    }

    @Test
    void decodingRandomBytesThrowsOnlyProtocolException() {
        java.util.Random random = new java.util.Random(1998);
        String valid = codec.encode(Samples.of("Perception"));
        for (int i = 0; i < 5_000; i++) {
            char[] chars = valid.toCharArray();
            for (int k = 0; k < 1 + random.nextInt(4); k++) {
                chars[random.nextInt(chars.length)] = (char) (32 + random.nextInt(95));
            }
            String mutated = new String(chars);
            try {
                codec.decode(mutated);
            } catch (ProtocolException expected) {
                assertThat(expected.getMessage()).isNotBlank();
            }
        }
    }
}
