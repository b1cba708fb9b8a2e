package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Percept;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.WorldGenerator;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Encoding a tick's worth of output for 1,000 agents, as the network threads do it: every agent's
 * client gets, as in the load test, the results of its move and perception request, the
 * {@code Tick} and its perception, in the ordinary form (six lines) or the lean one (three, or two
 * without the accepted move's result), each client's lines into one buffer. The messages are those
 * of a real tick of the benchmark world (1,000 × 1,000 units, 10,000 objects; sight 50, 120°).
 * {@link #viewerBroadcasts} is the tick's {@code AgentMoved} for viewers, each encoded once for all
 * of them (by the first network thread that writes it).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class TickOutputBenchmark {

    @Param({"1000"})
    int agents;

    @Param({"ordinary", "lean"})
    String form;

    private final List<List<Object>> batches = new ArrayList<>();
    private final List<ServerMessage> broadcasts = new ArrayList<>();
    private ClientForms forms;
    private ByteBuf buffer;

    /** One agent's client: keeps what a tick sends it, in the order sent, as a {@code NettySession} does. */
    private static final class Capture implements ClientSession {
        private final long id;
        private final Role role;
        final List<Object> sent = new ArrayList<>();

        Capture(long id, Role role) {
            this.id = id;
            this.role = role;
        }

        @Override
        public long id() {
            return id;
        }

        @Override
        public Role role() {
            return role;
        }

        @Override
        public void send(ServerMessage message) {
            sent.add(message);
        }

        @Override
        public void send(Percept percept) {
            sent.add(percept);
        }

        @Override
        public void send(EncodedLine line) {
            sent.add(line);
        }

        @Override
        public void flush() {}

        @Override
        public void close(ErrorMessage last) {}

        @Override
        public boolean isOpen() {
            return true;
        }
    }

    @Setup(Level.Trial)
    public void setUp() {
        forms = form.equals("lean")
                ? ClientForms.of(new HelloMessage(1, 2, Role.AGENT, "bench", null, null, List.of("LeanPerception")))
                : ClientForms.ORDINARY;
        Simulation sim = new Simulation(WorldGenerator.benchmark(2026).generate(),
                new SimulationConfig(20, ClockMode.LOCKSTEP, 1e6, 0, Duration.ofSeconds(1), agents, BodyLimits.DEFAULT),
                2026, "bench", Recorder.NONE, List.of());
        Capture viewer = new Capture(0, Role.VIEWER);
        sim.connected(viewer);
        List<Capture> clients = new ArrayList<>();
        Body body = new Body(0.5, 1.5, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(50, Math.toRadians(120)));
        long seq = 0;
        for (int i = 0; i < agents; i++) {
            Capture client = new Capture(i + 1, Role.AGENT);
            clients.add(client);
            sim.connected(client);
            sim.received(client, new RegisterMessage(++seq, "A" + i, body, null));
            sim.received(client, new PerceptionRequestMessage(++seq, "A" + i, 0));
        }
        sim.applyNow();
        // The game would wait for every agent's setup turn: started at once, so that ticks perceive.
        sim.start();
        SplittableRandom random = new SplittableRandom(2026);
        for (int tick = 0; tick < 3; tick++) {
            clients.forEach(client -> client.sent.clear());
            viewer.sent.clear();
            sim.beginTick();
            for (int i = 0; i < agents; i++) {
                Capture client = clients.get(i);
                Percept seen = (Percept) client.sent.stream().filter(Percept.class::isInstance).findFirst()
                        .orElseThrow();
                Vec3 here = seen.position();
                sim.received(client, new MoveMessage(++seq, "A" + i, here, Vec3.ground(
                        here.x() + random.nextDouble(-2, 2), here.z() + random.nextDouble(-2, 2))));
                sim.received(client, new PerceptionRequestMessage(++seq, "A" + i, 0));
            }
            clients.forEach(client -> client.sent.clear());
            viewer.sent.clear();
            sim.endTick();
        }
        // What the clients got from the last end of a tick and from the start of the next.
        sim.beginTick();
        for (Capture client : clients) {
            List<Object> batch = new ArrayList<>();
            for (Object message : client.sent) {
                if (!(message instanceof ServerMessage plain) || forms.sends(plain)) {
                    batch.add(message);
                }
            }
            batches.add(batch);
        }
        for (Object message : viewer.sent) {
            if (message instanceof EncodedLine line && !(line.message() instanceof io.orchard.protocol.message.TickMessage)) {
                broadcasts.add(line.message());
            }
        }
        buffer = Unpooled.directBuffer(1 << 16);
    }

    /** Every agent's client's lines of the tick, each client's into the buffer a network thread writes from. */
    @Benchmark
    public long agents() {
        long bytes = 0;
        for (List<Object> batch : batches) {
            buffer.clear();
            TickLines.write(batch, 0, forms, buffer);
            bytes += buffer.readableBytes();
        }
        return bytes;
    }

    /** The tick's broadcasts to viewers (one {@code AgentMoved} a move), each encoded once for every viewer. */
    @Benchmark
    public long viewerBroadcasts() {
        long bytes = 0;
        for (ServerMessage message : broadcasts) {
            bytes += new EncodedLine(message).bytes(TickLines::encode).length;
        }
        return bytes;
    }
}
