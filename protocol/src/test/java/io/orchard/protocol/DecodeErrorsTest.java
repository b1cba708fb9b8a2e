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

    /** Builds a Say line whose text holds the given bytes, at byte offset {@link #SAY_TEXT_AT}. */
    private static byte[] sayWith(String hexBytes) {
        byte[] head = "{\"type\":\"Say\",\"seq\":1,\"agent\":\"Guppy\",\"text\":\"a".getBytes(StandardCharsets.US_ASCII);
        byte[] tail = "b\"}".getBytes(StandardCharsets.US_ASCII);
        byte[] middle = java.util.HexFormat.ofDelimiter(" ").parseHex(hexBytes);
        byte[] line = java.util.Arrays.copyOf(head, head.length + middle.length + tail.length);
        System.arraycopy(middle, 0, line, head.length, middle.length);
        System.arraycopy(tail, 0, line, head.length + middle.length, tail.length);
        return line;
    }

    private static final int SAY_TEXT_AT = 47;

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        overlong slash, two bytes      | c0 af          | 0 | overlong
        overlong letter, two bytes     | c1 81          | 0 | overlong
        overlong slash, three bytes    | e0 80 af       | 0 | overlong
        overlong slash, four bytes     | f0 80 80 af    | 0 | overlong
        high surrogate                 | ed a0 80       | 0 | surrogate
        low surrogate                  | ed bf bf       | 0 | surrogate
        beyond U+10FFFF                | f4 90 80 80    | 0 | beyond U+10FFFF
        lead byte beyond F4            | f5 80 80 80    | 0 | never part of UTF-8
        byte FF                        | ff             | 0 | never part of UTF-8
        stray continuation byte        | 80             | 0 | never begun
        second byte not a continuation | e2 28 a1       | 1 | does not continue
        third byte not a continuation  | e2 82 28       | 2 | does not continue
        """)
    void bytesThatAreNotStrictUtf8AreMalformedNamingTheirOffset(String name, String hex, int into, String what) {
        assertThatThrownBy(() -> codec.decode(sayWith(hex)))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining("invalid UTF-8 at byte " + (SAY_TEXT_AT + into))
                .hasMessageContaining(what)
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.MALFORMED_JSON);
    }

    @Test
    void aSequenceCutShortByTheEndOfTheLineIsMalformed() {
        byte[] line = java.util.Arrays.copyOf(sayWith("e2 82"), SAY_TEXT_AT + 2);
        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining("invalid UTF-8 at byte " + SAY_TEXT_AT + ": a sequence of 3 bytes cut short");
    }

    @Test
    void aNameSpelledWithAnOverlongLetterIsRefusedNotReadAsTheLetter() {
        byte[] head = "{\"type\":\"Unregister\",\"seq\":1,\"agent\":\"A".getBytes(StandardCharsets.US_ASCII);
        byte[] line = java.util.Arrays.copyOf(head, head.length + 5);
        line[head.length] = (byte) 0xc1;
        line[head.length + 1] = (byte) 0x81;
        line[head.length + 2] = 'b';
        line[head.length + 3] = '"';
        line[head.length + 4] = '}';
        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining("invalid UTF-8 at byte " + head.length)
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.MALFORMED_JSON);
    }

    @ParameterizedTest(name = "U+{0}")
    @CsvSource(delimiter = '|', textBlock = """
        0080   | c2 80
        07FF   | df bf
        0800   | e0 a0 80
        D7FF   | ed 9f bf
        E000   | ee 80 80
        FFFD   | ef bf bd
        10000  | f0 90 80 80
        10FFFF | f4 8f bf bf
        """)
    void everyWellFormedEdgeOfUtf8IsRead(String codePoint, String hex) {
        SayMessage say = (SayMessage) codec.decode(sayWith(hex));
        assertThat(say.text()).isEqualTo("a" + Character.toString(Integer.parseInt(codePoint, 16)) + "b");
    }

    @ParameterizedTest(name = "{0} bytes")
    @CsvSource({"4194305", "4194306"})
    void aModelOfMoreThan4MiBIsRefusedWhateverItsPadding(int size) {
        String data = java.util.Base64.getEncoder().encodeToString(new byte[size]);
        assertThatThrownBy(() -> new ModelSpec(ModelFormat.GLB, null, data))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("data must decode to at most 4194304 bytes");
        String line = "{\"type\":\"Register\",\"seq\":2,\"name\":\"Guppy\",\"body\":{\"radius\":0.5,\"height\":1.2,"
                + "\"maxSpeed\":8,\"gripper\":{\"part\":\"hands\",\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},"
                + "\"sight\":{\"range\":30,\"fieldOfView\":3.14}},\"model\":{\"format\":\"glb\",\"data\":\"" + data + "\"}}";
        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining("data must decode to at most 4194304 bytes, it decodes to " + size)
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.INVALID_VALUE);
    }

    @Test
    void aModelOfExactly4MiBIsTaken() {
        byte[] model = new byte[ModelSpec.MAX_MODEL_BYTES];
        assertThat(ModelSpec.of(ModelFormat.GLB, model).bytes()).hasSize(4_194_304);
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
