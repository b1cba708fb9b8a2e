package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolException;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.value.Vec3;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The plain Move and PerceptionRequest lines read without the mapper, exactly as the codec reads them. */
class FastMovesTest {

    private static final MessageCodec CODEC = new MessageCodec();

    private static ClientMessage fast(String line) {
        byte[] bytes = line.getBytes(StandardCharsets.UTF_8);
        return FastMoves.read(bytes, bytes.length);
    }

    /** Read here, and equal to what the codec reads. */
    private static void readAsTheCodecReads(String line) {
        ClientMessage fast = fast(line);
        assertThat(fast).as(line).isNotNull();
        assertThat(fast).as(line).isEqualTo(CODEC.decodeClient(line));
    }

    @Test
    void whatTheCodecWritesIsReadHereAsTheCodecReadsIt() {
        Random random = new Random(14);
        for (int i = 0; i < 2000; i++) {
            Vec3 from = i % 3 == 0 ? null : new Vec3(random.nextDouble(-600, 600), i % 5 == 0 ? 0 : random.nextDouble(),
                    i % 7 == 0 ? Math.rint(random.nextDouble(-600, 600)) : random.nextDouble(-1e-6, 1e-6));
            Vec3 to = new Vec3(random.nextGaussian() * Math.pow(10, random.nextInt(-12, 12)), 0,
                    random.nextInt(-1000, 1000) / 100.0);
            readAsTheCodecReads(CODEC.encode(new MoveMessage(random.nextLong(0, 1_000_000_000_000_000_000L), "Agent_" + i, from,
                    to)));
            readAsTheCodecReads(CODEC.encode(new PerceptionRequestMessage(random.nextInt(0, 1000), "a-" + i,
                    random.nextInt(0, Integer.MAX_VALUE))));
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "{\"type\":\"Move\",\"seq\":0,\"agent\":\"A\",\"from\":{\"x\":1.25,\"y\":0,\"z\":-3.5},\"to\":{\"x\":2,\"y\":0,\"z\":-4}}",
        "{\"type\":\"Move\",\"seq\":7,\"agent\":\"A\",\"to\":{\"x\":-0,\"y\":-0.0,\"z\":1E2}}",
        "{\"type\":\"Move\",\"seq\":999999999999999999,\"agent\":\"A\",\"to\":{\"x\":1.0E-4,\"y\":0,\"z\":1e+2}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":123456789012345678,\"y\":0,\"z\":0.1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":2.2250738585072011e-308,\"y\":0,\"z\":9007199254740993}}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy\",\"every\":0}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy\",\"every\":2147483647}",
    })
    void plainLinesAreReadAsTheCodecReadsThem(String line) {
        readAsTheCodecReads(line);
    }

    /** Anything else is the codec's: it reads it, or refuses it with the error it always gave. */
    @ParameterizedTest
    @ValueSource(strings = {
        "{\"type\":\"Move\",\"seq\":01,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":-1,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1.0,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":9223372036854775808,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A b\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\\u0062\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1e999,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":01,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1.,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":.5,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1},\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}} ",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"from\":null,\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1,\"z\":1}}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\"}",
        "{\"type\":\"Move\",\"seq\":1,\"agent\":\"A\",\"to\":{\"x\":12345678901234567890,\"y\":0,\"z\":1}}",
        "{\"type\":\"Move\", \"seq\":1,\"agent\":\"A\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy\",\"every\":-1}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy\",\"every\":2147483648}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy\"}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy\",\"every\":1,\"x\":1}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"\",\"every\":1}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"G\u00fcppy\",\"every\":1}",
        "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"Guppy",
        "{\"type\":\"Tick\",\"tick\":3,\"time\":0.15}",
    })
    void otherLinesAreLeftToTheCodec(String line) {
        assertThat(fast(line)).as(line).isNull();
    }

    @Test
    void aValueTheMessageRefusesIsLeftToTheCodecAndItsError() {
        List<String> refused = List.of(
                "{\"type\":\"Move\",\"seq\":1,\"agent\":\"9lives\",\"to\":{\"x\":1,\"y\":0,\"z\":1}}",
                "{\"type\":\"PerceptionRequest\",\"seq\":3,\"agent\":\"" + "a".repeat(40) + "\",\"every\":1}");
        for (String line : refused) {
            assertThat(fast(line)).as(line).isNull();
            assertThatThrownBy(() -> CODEC.decodeClient(line)).isInstanceOf(ProtocolException.class);
        }
    }
}
