package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The fast writer must write exactly the codec's bytes, whatever the numbers and strings. */
class FastLinesTest {

    private static final MessageCodec CODEC = new MessageCodec();

    private final Random random = new Random(7);

    private static String fast(ServerMessage message) {
        ByteBuf out = Unpooled.buffer();
        assertThat(FastLines.write(message, out)).isTrue();
        return out.toString(StandardCharsets.UTF_8);
    }

    private static void same(ServerMessage message) {
        assertThat(fast(message)).isEqualTo(new String(CODEC.encodeLine(message), StandardCharsets.UTF_8));
    }

    /** Numbers as the server makes them (rounded) or not (anything), in every range. */
    private double number() {
        return switch (random.nextInt(6)) {
            case 0 -> Math.round((random.nextDouble() - 0.5) * 2000 * 100) / 100.0;
            case 1 -> Math.round((random.nextDouble() - 0.5) * 7 * 1000) / 1000.0;
            case 2 -> (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(30) - 15);
            case 3 -> new double[] {0.0, -0.0, 1e-3, 9.999e6, 1e7, 0.0015, 1e-4, 123456.789, Math.PI}[random.nextInt(9)];
            case 4 -> Math.round(random.nextDouble() * 100) / 1.0;
            default -> Math.round(random.nextGaussian() * 1e6) / 1000.0;
        };
    }

    private RelativePosition at() {
        return new RelativePosition(Math.abs(number()), Math.max(-3.14, Math.min(Math.PI, number() % 3)));
    }

    private String id() {
        return new String[] {"T17", "D2", "F12", "B1", "F\"quoted\"", "Fé", "T\\1", "F☃"}[random.nextInt(8)];
    }

    @Test
    void perceptionsOfEveryKindAreWrittenAsTheCodecWritesThem() {
        for (int n = 0; n < 2000; n++) {
            List<PerceivedObject> objects = new ArrayList<>();
            for (int i = random.nextInt(30); i > 0; i--) {
                objects.add(new PerceivedObject(id(), random.nextBoolean() ? ObjectKind.TREE : ObjectKind.TABLE, at(),
                        Math.abs(number()) + 0.01, Math.abs(number()) + 0.01));
            }
            List<PerceivedAgent> agents = new ArrayList<>();
            for (int i = random.nextInt(4); i > 0; i--) {
                agents.add(new PerceivedAgent("Agent" + i, at(), number(), 0.5));
            }
            List<PerceivedFruit> fruit = new ArrayList<>();
            for (int i = random.nextInt(8); i > 0; i--) {
                fruit.add(new PerceivedFruit(id(), FruitKind.values()[random.nextInt(3)], new Vec3(number(), number(),
                        number()), 0.25, random.nextBoolean() ? null : id()));
            }
            same(new PerceptionMessage(random.nextInt(100_000), "Guppy", new Vec3(number(), 0, number()), number(),
                    objects, agents, fruit));
        }
    }

    @Test
    void landmarksCastleTicksMovesAndResultsAreWrittenAsTheCodecWritesThem() {
        for (int n = 0; n < 2000; n++) {
            List<PerceivedBridge> bridges = new ArrayList<>();
            for (int i = random.nextInt(3); i > 0; i--) {
                bridges.add(new PerceivedBridge(id(), at(), at(), Math.abs(number()) + 0.01));
            }
            same(new LandmarkPerceptionMessage(n, "Guppy", random.nextBoolean() ? null
                    : new PerceivedRiver(at(), number()), bridges));
            same(new CastlePerceptionMessage(n, "Guppy", Sector.values()[random.nextInt(8)]));
            same(new TickMessage(random.nextLong() & Long.MAX_VALUE, Math.abs(number())));
            same(new AgentMovedMessage(random.nextLong() & Long.MAX_VALUE, "Guppy", new Vec3(number(), number(),
                    number()), new Vec3(number(), 0, number()), Math.abs(number()), Math.abs(number())));
            same(new ActionResultMessage(random.nextLong() & Long.MAX_VALUE, random.nextBoolean() ? null : "Guppy",
                    "Move", Outcome.values()[random.nextInt(3)], random.nextBoolean() ? null
                    : "path crosses tree \"T17\" \n é", random.nextBoolean() ? null : new Vec3(number(), 0, number()),
                    Math.abs(number())));
        }
    }

    @ParameterizedTest
    @ValueSource(doubles = {0.0, -0.0, 0.001, -0.001, 0.0009999, 0.1, 0.30000000000000004, 12.5, -40.25, 1e-5, 9999999.999,
        1e7, 1.0E-4, 2.2, 4.9E-324, 1.7976931348623157E308, 3.141592653589793, 100.0, 1000000.0})
    void aNumberIsWrittenAsTheCodecWritesIt(double value) {
        same(new TickMessage(1, Math.abs(value)));
        same(new ActionResultMessage(1, null, "Move", Outcome.ACCEPTED, null, new Vec3(value, -value, value), 0));
    }

    @Test
    void otherMessagesAreLeftToTheCodec() {
        ByteBuf out = Unpooled.buffer();
        assertThat(FastLines.write(new WelcomeMessage(1, 1, "x", Role.AGENT, new Bounds(0, 0, 1, 1), 20,
                ClockMode.REALTIME, 0), out)).isFalse();
        assertThat(out.readableBytes()).isZero();
    }
}
