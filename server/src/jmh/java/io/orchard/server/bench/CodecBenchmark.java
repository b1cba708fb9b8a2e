package io.orchard.server.bench;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * The codec on the two lines that dominate traffic: a small action (a move) and a perception of 50
 * things, with numbers rounded as the server rounds them.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class CodecBenchmark {

    private final MessageCodec codec = new MessageCodec();
    private MoveMessage move;
    private PerceptionMessage perception;
    private byte[] moveLine;
    private byte[] perceptionLine;

    @Setup
    public void setUp() {
        move = new MoveMessage(1234, "Guppy", new Vec3(12.34, 0, -40.25), new Vec3(20.5, 0, -35.75));
        List<PerceivedObject> objects = new ArrayList<>();
        List<PerceivedFruit> fruit = new ArrayList<>();
        for (int i = 0; i < 35; i++) {
            objects.add(new PerceivedObject("T" + (100 + i), i % 5 == 0 ? ObjectKind.TABLE : ObjectKind.TREE,
                    new RelativePosition(3.17 + i, -1.047 + i * 0.05), 1.25, 6.5));
        }
        for (int i = 0; i < 12; i++) {
            fruit.add(new PerceivedFruit("F" + i, FruitKind.values()[i % 3], new Vec3(10.25 + i, 0.15, -30.5 - i),
                    0.15, i % 2 == 0 ? null : "T10" + i));
        }
        List<PerceivedAgent> agents = List.of(new PerceivedAgent("Bunny", new RelativePosition(4.5, 0.3), 1.2, 0.4),
                new PerceivedAgent("Robot", new RelativePosition(14.2, -0.7), -2.1, 0.6),
                new PerceivedAgent("Dwarf", new RelativePosition(21.05, 0.91), 0.0, 0.5));
        perception = new PerceptionMessage(4242, "Guppy", new Vec3(12.34, 0, -40.25), 0.785, objects, agents, fruit);
        moveLine = codec.encodeLine(move);
        perceptionLine = codec.encodeLine(perception);
    }

    @Benchmark
    public byte[] encodeMove() {
        return codec.encodeLine(move);
    }

    @Benchmark
    public Object decodeMove() {
        return codec.decode(moveLine);
    }

    @Benchmark
    public byte[] encodePerception() {
        return codec.encodeLine(perception);
    }

    @Benchmark
    public Object decodePerception() {
        return codec.decode(perceptionLine);
    }
}
