package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Framing and decoding on an embedded channel: lines split across writes, bad lines, long lines. */
class MessageDecoderTest {

    private final EmbeddedChannel channel = new EmbeddedChannel(
            new LineBasedFrameDecoder(MessageCodec.MAX_LARGE_LINE_BYTES + 1, true, true),
            new MessageDecoder(new MessageCodec()));

    private void write(String text) {
        channel.writeInbound(Unpooled.copiedBuffer(text, StandardCharsets.UTF_8));
    }

    @Test
    void aLineSplitAcrossWritesDecodesOnceWhole() {
        write("{\"type\":\"EndTu");
        assertThat((Object) channel.readInbound()).isNull();
        write("rn\",\"seq\":3,\"tick\":7}\r\n{\"type\":\"EndTurn\",\"seq\":4,\"tick\":8}\n");
        assertThat((Object) channel.readInbound()).isEqualTo(new EndTurnMessage(3, 7));
        assertThat((Object) channel.readInbound()).isEqualTo(new EndTurnMessage(4, 8));
        assertThat(channel.finish()).isFalse();
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        not JSON             | hello there                                  | malformed_json | 0
        NaN                  | {"type":"EndTurn","seq":5,"tick":NaN}        | malformed_json | 5
        huge integer         | {"type":"EndTurn","seq":5,"tick":99999999999999999999} | invalid_value | 5
        negative seq         | {"type":"EndTurn","seq":-1,"tick":1}        | invalid_value  | 0
        unknown type         | {"type":"Teleport","seq":6}                  | unknown_type   | 6
        server's message     | {"type":"Tick","tick":1,"time":0}            | wrong_direction | 0
        missing field        | {"type":"Move","seq":8,"agent":"Guppy"}      | missing_field  | 8
        duplicate key        | {"type":"EndTurn","seq":1,"seq":2,"tick":2}  | malformed_json | 1
        seq of two to the 63 | {"type":"EndTurn","seq":9223372036854775808,"tick":2} | invalid_value | 0
        seq of 19 digits     | {"type":"EndTurn","seq":9223372036854775807,"tick":-2} | invalid_value | 9223372036854775807
        fraction for a seq   | {"type":"EndTurn","seq":1.5,"tick":2}        | invalid_value  | 0
        seq in a string      | {"type":"Say","seq":"x","agent":"A","text":"\"seq\":4"} | invalid_value | 0
        bundled no_such_model | {"type":"Register","seq":3,"name":"G","body":{"radius":0.5,"height":1.2,"maxSpeed":8,"gripper":{"part":"hands","reach":0.6,"minHeight":0,"maxHeight":1.5},"sight":{"range":30,"fieldOfView":3}},"model":{"format":"bundled","bundled":"no_such_model"}} | invalid_value | 3
        """)
    void aBadLineIsAnsweredWithItsErrorAndTheConnectionStaysOpen(String name, String line, String code, long seq) {
        write(line + "\n");
        assertThat((Object) channel.readInbound()).isNull();
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code().wireName()).isEqualTo(code);
        assertThat(error.seq()).isEqualTo(seq);
        assertThat(channel.isOpen()).isTrue();
        write("{\"type\":\"EndTurn\",\"seq\":9,\"tick\":1}\n");
        assertThat((Object) channel.readInbound()).isEqualTo(new EndTurnMessage(9, 1));
    }

    @Test
    void theErrorsOfTheIssueAreToldInTheProtocolsWords() {
        channel.writeInbound(Unpooled.wrappedBuffer(new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF}),
                Unpooled.copiedBuffer("{\"type\":\"EndTurn\",\"seq\":3,\"tick\":2}\n", StandardCharsets.UTF_8));
        ErrorMessage bom = channel.readOutbound();
        assertThat(bom.text()).contains("byte-order mark").doesNotContain("'o'");
        write("{\"type\":\"Move\",\"seq\":4,\"agent\":\"G\",\"from\":{\"x\":NaN,\"y\":0,\"z\":0},"
                + "\"to\":{\"x\":1,\"y\":0,\"z\":0}}\n");
        ErrorMessage nan = channel.readOutbound();
        assertThat(nan.code()).isEqualTo(ErrorCode.MALFORMED_JSON);
        assertThat(nan.seq()).isEqualTo(4);
        assertThat(nan.text()).contains("from.x must be a finite number, was NaN").doesNotContain("Feature");
        write("{\"type\":\"Hello\",\"seq\":5,\"protocolVersion\":2,\"role\":\"Agent\",\"client\":\"c\"}\n");
        ErrorMessage role = channel.readOutbound();
        assertThat(role.text()).isEqualTo("role must be one of 'agent', 'viewer', was the string 'Agent'");
        write("{\"type\":\"EndTurn\",\"seq\":6,\"tick\":\"7\"}\n");
        assertThat(((ErrorMessage) channel.readOutbound()).text()).isEqualTo("tick must be an integer, was the string '7'");
    }

    /** Found by fuzzing: the codec quoted the whole bad value, and an error's text may hold 1,000 characters. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        a long unknown type   | {"type":"%s","seq":3}
        a long enum value     | {"type":"GameControl","seq":3,"command":"%s"}
        a long duplicate key  | {"type":"EndTurn","seq":3,"tick":1,"%s":1,"%<s":2}
        a long string number  | {"type":"EndTurn","seq":3,"tick":"%s"}
        """)
    void anErrorAboutAHugeValueIsCutToWhatAnErrorMayCarry(String name, String template) {
        write(String.format(template, "x".repeat(1500)) + "\n");
        ErrorMessage error = channel.readOutbound();
        assertThat(error.seq()).isEqualTo(3);
        // The codec shows at most 40 characters of a value it quotes, and the decoder cuts the whole text to 1,000.
        assertThat(error.text()).hasSizeLessThanOrEqualTo(1000).contains("x".repeat(40) + "...")
                .doesNotContain("x".repeat(41));
        assertThat(channel.isOpen()).isTrue();
    }

    @Test
    void anOrdinaryMessageLongerThanItsLimitClosesTheConnection() {
        write("{\"type\":\"Say\",\"seq\":2,\"agent\":\"Guppy\",\"text\":\"" + "x".repeat(MessageCodec.MAX_LINE_BYTES)
                + "\"}\n");
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.LINE_TOO_LONG);
        assertThat(error.seq()).isEqualTo(2);
        assertThat(channel.isOpen()).isFalse();
    }
}
