package io.orchard.server.bench;

import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.WorldGenerator;
import java.time.Duration;
import java.util.List;
import java.util.Random;
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
 * One whole tick of the simulation on one thread: 1,000 agents in a 1,000 × 1,000 world of 10,000
 * trees, tables and fruit, every agent perceiving every tick (range 50, a 120° cone) and a tenth of
 * them starting a move each tick. Sessions drop what they are sent, so this is the simulation's own
 * cost: encoding happens on the network threads and is measured by {@link CodecBenchmark}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class TickBenchmark {

    @Param({"1000"})
    int agents;

    private Simulation sim;
    private NullSession session;
    private final Random random = new Random(42);
    private long seq;

    @Setup(Level.Trial)
    public void setUp() {
        sim = new Simulation(WorldGenerator.benchmark(2026).generate(),
                new SimulationConfig(20, ClockMode.LOCKSTEP, 1e6, 0, Duration.ofSeconds(1), agents, BodyLimits.DEFAULT),
                2026, "bench", Recorder.NONE, List.of());
        session = new NullSession(1, Role.AGENT);
        sim.connected(session);
        Body body = new Body(0.5, 1.5, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(50, Math.toRadians(120)));
        for (int i = 0; i < agents; i++) {
            sim.received(session, new RegisterMessage(++seq, "A" + i, body, null));
        }
        sim.applyNow();
        // The game would wait for every agent's setup turn: started at once, so that ticks pass.
        sim.start();
        for (int i = 0; i < agents; i++) {
            sim.received(session, new PerceptionRequestMessage(++seq, "A" + i, 1));
        }
        sim.beginTick();
        sim.endTick();
    }

    @Benchmark
    public long tick() {
        sim.beginTick();
        for (int i = 0; i < agents / 10; i++) {
            String name = "A" + random.nextInt(agents);
            // From the origin: most are refused as teleports, the cheap path; the rest walk.
            sim.received(session, new MoveMessage(++seq, name, Vec3.ZERO, Vec3.ground(random.nextDouble() * 10,
                    random.nextDouble() * 10)));
        }
        sim.endTick();
        return session.messages;
    }
}
