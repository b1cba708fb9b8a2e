package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The lean writer must write exactly the codec's bytes for the lean record of the same perception. */
class LeanLinesTest {

    private static final MessageCodec CODEC = new MessageCodec();

    private final Random random = new Random(11);

    private static void same(PerceptionMessage seen, LandmarkPerceptionMessage landmarks, CastlePerceptionMessage castle) {
        ByteBuf out = Unpooled.buffer();
        LeanLines.write(seen, landmarks, castle, out);
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo(new String(CODEC.encodeLine(
                LeanPerceptionMessage.of(seen, landmarks, castle)), StandardCharsets.UTF_8));
    }

    /** Lengths as the server rounds them, or not rounded at all, small and large. */
    private double length() {
        return switch (random.nextInt(4)) {
            case 0 -> Math.round((random.nextDouble() - 0.5) * 20_000 * 100) / 100.0;
            case 1 -> (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(10) - 4);
            case 2 -> new double[] {0.0, -0.0, 0.005, -0.005, 0.015, 0.0049999, 10_000, -10_000}[random.nextInt(8)];
            default -> Math.round(random.nextGaussian() * 1e5) / 1000.0;
        };
    }

    private double size() {
        return Math.abs(length()) + 1e-4;
    }

    private double angle() {
        return random.nextInt(10) == 0 ? Math.PI : Math.round((random.nextDouble() - 0.5) * 6.28 * 1000) / 1000.0;
    }

    private RelativePosition at() {
        return new RelativePosition(Math.abs(length()), angle());
    }

    private String id() {
        return new String[] {"T17", "D2", "F12", "B1", "F\"quoted\"", "Fé", "T\\1", "F☃"}[random.nextInt(8)];
    }

    @Test
    void perceptionsOfEveryKindAreWrittenAsTheCodecWritesTheirLeanRecord() {
        for (int n = 0; n < 2000; n++) {
            List<PerceivedObject> objects = new ArrayList<>();
            for (int i = random.nextInt(30); i > 0; i--) {
                objects.add(new PerceivedObject(id(), random.nextBoolean() ? ObjectKind.TREE : ObjectKind.TABLE, at(),
                        size(), size()));
            }
            List<PerceivedAgent> agents = new ArrayList<>();
            for (int i = random.nextInt(4); i > 0; i--) {
                agents.add(new PerceivedAgent("Agent" + i, at(), angle(), size()));
            }
            List<PerceivedFruit> fruit = new ArrayList<>();
            for (int i = random.nextInt(8); i > 0; i--) {
                fruit.add(new PerceivedFruit(id(), FruitKind.values()[random.nextInt(3)], new Vec3(length(), length(),
                        length()), 0.25, random.nextBoolean() ? null : id()));
            }
            List<PerceivedBridge> bridges = new ArrayList<>();
            for (int i = random.nextInt(3); i > 0; i--) {
                bridges.add(new PerceivedBridge(id(), at(), at(), size()));
            }
            long tick = random.nextInt(100_000);
            same(new PerceptionMessage(tick, "Guppy", new Vec3(length(), length(), length()),
                            random.nextBoolean() ? angle() : length(), objects, agents, fruit),
                    new LandmarkPerceptionMessage(tick, "Guppy", random.nextBoolean() ? null
                            : new PerceivedRiver(at(), angle()), bridges),
                    new CastlePerceptionMessage(tick, "Guppy", Sector.values()[random.nextInt(8)]));
        }
    }

    @Test
    void anEmptyViewIsWrittenAsTheCodecWritesIt() {
        same(new PerceptionMessage(0, "A", Vec3.ZERO, 0, List.of(), List.of(), List.of()),
                new LandmarkPerceptionMessage(0, "A", null, List.of()), new CastlePerceptionMessage(0, "A", Sector.NORTH));
    }
}
