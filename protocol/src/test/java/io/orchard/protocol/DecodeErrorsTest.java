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

    /** Words of the reader's and of Java's that a client must never see in an error. */
    private static final String IMPLEMENTATION_WORDS = "Feature|Config|Constraints|Jackson|JsonToken|io\\.orchard|java\\."
            + "|tools\\.|\\w\\[\\w+=|[Cc]reator|[Dd]eserializ|Input byte|Illegal base64";

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
        duplicate key                  | {"type":"EndTurn","seq":1,"seq":2,"tick":2}                   | malformed_json  | duplicate key
        empty line                     | ''                                                            | malformed_json  | empty line
        message of the other direction | {"type":"Tick","tick":1,"time":0}                             | wrong_direction | sent by the server
        """)
    void badLinesAreRefusedNamingTheProblem(String name, String line, String code, String fragment) {
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessageContaining(fragment)
                .extracting(e -> ((ProtocolException) e).code().wireName()).isEqualTo(code);
    }

    /** Each line of the issue and of docs/protocol.md section 2.7, with the whole text the client gets back. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', textBlock = """
        NaN names its field              | {"type":"Move","seq":6,"agent":"Guppy","from":{"x":NaN,"y":0,"z":2},"to":{"x":1,"y":0,"z":2}} | malformed_json | malformed JSON at column 55: from.x must be a finite number, was NaN (not JSON)
        Infinity in an array             | {"type":"ScoreUpdate","tick":1,"scores":[{"agent":"A","points":Infinity,"fruit":1}]} | malformed_json | malformed JSON at column 72: scores[0].points must be a finite number, was Infinity (not JSON)
        -Infinity at the top             | {"type":"Tick","tick":1,"time":-Infinity}             | malformed_json  | malformed JSON at column 41: time must be a finite number, was -Infinity (not JSON)
        string for an integer            | {"type":"EndTurn","seq":1,"tick":"7"}                 | invalid_value   | tick must be an integer, was the string '7'
        fraction for an integer          | {"type":"EndTurn","seq":1,"tick":7.5}                 | invalid_value   | tick must be an integer, without fraction or exponent, was 7.5
        exponent for an integer          | {"type":"EndTurn","seq":1,"tick":1e2}                 | invalid_value   | tick must be an integer, without fraction or exponent, was 1e2
        null for an integer              | {"type":"EndTurn","seq":1,"tick":null}                | invalid_value   | tick must be an integer, was null
        boolean for an integer           | {"type":"EndTurn","seq":1,"tick":true}                | invalid_value   | tick must be an integer, was true
        array for an integer             | {"type":"EndTurn","seq":1,"tick":[1]}                 | invalid_value   | tick must be an integer, was an array
        seq of two to the 63             | {"type":"EndTurn","seq":9223372036854775808,"tick":2} | invalid_value   | seq must be an integer from -9223372036854775808 to 9223372036854775807, was 9223372036854775808
        int32 out of range               | {"type":"PerceptionRequest","seq":1,"agent":"A","every":4294967296} | invalid_value | every must be an integer from -2147483648 to 2147483647, was 4294967296
        number for a string              | {"type":"Say","seq":1,"agent":"Guppy","text":12}      | invalid_value   | text must be a string, was 12
        boolean for a string             | {"type":"Say","seq":1,"agent":"Guppy","text":false}   | invalid_value   | text must be a string, was false
        enum in the wrong case           | {"type":"Hello","seq":1,"protocolVersion":2,"role":"Agent","client":"c"} | invalid_value | role must be one of 'agent', 'viewer', was the string 'Agent'
        number for an enum               | {"type":"Hello","seq":1,"protocolVersion":2,"role":5,"client":"c"} | invalid_value | role must be one of 'agent', 'viewer', was 5
        unknown command                  | {"type":"GameControl","seq":1,"command":"explode"}    | invalid_value   | command must be one of 'start', 'pause', 'resume', 'restart', was the string 'explode'
        an enum's index                  | {"type":"GameControl","seq":1,"command":1}            | invalid_value   | command must be one of 'start', 'pause', 'resume', 'restart', was 1
        a seed for a start               | {"type":"GameControl","seq":1,"command":"start","seed":5} | invalid_value | seed goes only with the command 'restart', was given with 'start'
        number for an object             | {"type":"Move","seq":6,"agent":"Guppy","from":5,"to":{"x":1,"y":0,"z":2}} | invalid_value | from must be an object, was 5
        string for a nested number       | {"type":"Move","seq":6,"agent":"Guppy","from":{"x":"1","y":0,"z":2},"to":{"x":1,"y":0,"z":2}} | invalid_value | from.x must be a number, was the string '1'
        object for a list                | {"type":"ScoreUpdate","tick":1,"scores":{}}           | invalid_value   | scores must be an array, was an object
        trailing comma                   | {"type":"EndTurn","seq":1,"tick":2,}                  | malformed_json  | malformed JSON at column 36 near tick: unexpected '}', expected a key in double quotes
        comment                          | {"type":"EndTurn" /* c */}                            | malformed_json  | malformed JSON at column 19 near type: comments are not JSON
        leading zero                     | {"type":"EndTurn","seq":01,"tick":2}                  | malformed_json  | malformed JSON at column 26 near seq: a number must not start with a 0 followed by more digits
        single quotes                    | {'type':'EndTurn'}                                    | malformed_json  | malformed JSON at column 2: unexpected a single quote, expected a key in double quotes
        truncated                        | {"type":"Move","seq":6                                | malformed_json  | malformed JSON at column 23 near seq: the line ends before the JSON object is complete
        raw tab in a string              | `{"type":"Say","seq":1,"agent":"A","text":"a\tb"}`    | malformed_json  | malformed JSON at column 44 near text: a control character (U+0009) must be escaped in a string
        bad escape                       | {"type":"Say","seq":1,"agent":"A","text":"\\q"}      | malformed_json  | malformed JSON at column 44 near text: '\\q' is not a JSON escape
        bare word                        | {"type":"EndTurn","seq":1,"tick":2} x                 | malformed_json  | malformed JSON at column 37: unexpected 'x', expected a value (a string, a number, an object, an array, true, false or null)
        vector in a reason               | {"type":"SetRotation","seq":1,"agent":"G","rotation":{"axis":{"x":0,"y":0,"z":0},"angle":1}} | invalid_value | rotation.axis must not be the zero vector
        not Base64                       | {"type":"Register","seq":2,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"glb","data":"QUJD!"}} | invalid_value | model.data must be Base64 (the standard alphabet A-Z, a-z, 0-9, '+', '/', with '=' padding), has '!' at character 4
        """)
    void errorsAreToldInTheProtocolsWordsNamingTheFieldAndTheValue(String name, String line, String code,
                                                                   String text) {
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessage(text)
                .extracting(e -> ((ProtocolException) e).code().wireName()).isEqualTo(code);
    }

    @Test
    void aByteOrderMarkIsNamedAsOneNotAsTheLetterItsBitsMake() {
        byte[] bom = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
        byte[] json = "{\"type\":\"EndTurn\",\"seq\":3,\"tick\":2}".getBytes(StandardCharsets.US_ASCII);
        byte[] line = java.util.Arrays.copyOf(bom, bom.length + json.length);
        System.arraycopy(json, 0, line, bom.length, json.length);
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessage("a line must hold one JSON object, it starts with a byte-order mark (bytes EF BB BF),"
                        + " which a line must not have")
                .satisfies(e -> assertThat(((ProtocolException) e).seq()).as("read past the mark").isEqualTo(3))
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.MALFORMED_JSON);
        assertThatThrownBy(() -> codec.decodeClient(new byte[] {(byte) 0xC3, (byte) 0xA9}))
                .hasMessage("a line must hold one JSON object, it starts with the byte C3");
    }

    @Test
    void nestingBeyondTheReadLimitIsNamedWithoutTheReadersWords() {
        String line = "{\"type\":\"EndTurn\",\"seq\":1,\"tick\":2,\"x\":" + "[".repeat(600) + "]".repeat(600) + "}";
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .hasMessage("malformed JSON: objects and arrays nest too deep (501, at most 500)")
                .extracting(e -> ((ProtocolException) e).code()).isEqualTo(ErrorCode.MALFORMED_JSON);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        a seq that was read              | {"type":"EndTurn","seq":12,"tick":-1}                  | 12
        a seq before a bad value         | {"type":"Move","seq":7,"agent":"no spaces"}            | 7
        a seq before malformed JSON      | {"type":"EndTurn","seq":8,"tick":,}                    | 8
        two to the 63                    | {"type":"EndTurn","seq":9223372036854775808,"tick":2}  | 0
        the largest                      | {"type":"EndTurn","seq":9223372036854775807,"tick":-2} | 9223372036854775807
        negative                         | {"type":"EndTurn","seq":-1,"tick":2}                   | 0
        a fraction                       | {"type":"EndTurn","seq":1.5,"tick":2}                  | 0
        an exponent                      | {"type":"EndTurn","seq":1e2,"tick":2}                  | 0
        a string                         | {"type":"EndTurn","seq":"5","tick":2}                  | 0
        only inside a nested object      | {"type":"Move","from":{"seq":5},"seq":true}            | 0
        only inside a string             | {"type":"Say","text":"\"seq\":5"}                    | 0
        after the error                  | {"type":"EndTurn","tick":2,,"seq":4}                   | 0
        of a message of the other side   | {"type":"Welcome","seq":9}                             | 9
        """)
    void theSeqOfABadLineIsEchoedOnlyWhenItIsOneTheClientCouldHaveMeant(String name, String line, long seq) {
        assertThatThrownBy(() -> codec.decodeClient(line))
                .isInstanceOf(ProtocolException.class)
                .extracting(e -> ((ProtocolException) e).seq()).isEqualTo(seq);
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
                assertThat(expected.getMessage()).isNotBlank().doesNotContainPattern(IMPLEMENTATION_WORDS);
            }
        }
    }
}
