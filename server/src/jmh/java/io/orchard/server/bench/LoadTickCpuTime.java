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
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The simulation's thread's share of the load test, on the thread's CPU clock ({@link CpuRounds}):
 * 1,000 agents, each on a connection of its own, every one asking for its perception every tick
 * and, on each, moving a step of up to 2 units from where it was perceived, as the load
 * generator's agents do; 5 viewers watch. Sessions keep only each agent's last perceived position,
 * so this is the tick's own cost without the network threads', but with making and queueing the
 * clients' messages, which the network threads do in a server.
 *
 * <pre>
 * java -cp ... io.orchard.server.bench.LoadTickCpuTime [agents 1000] [warm-up ticks 400] [rounds 10] [ticks a round 50]
 * </pre>
 */
public final class LoadTickCpuTime {

    private LoadTickCpuTime() {}

    /** Runs the rounds and prints them. */
    public static void main(String[] args) {
        int agents = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        Simulation sim = new Simulation(WorldGenerator.benchmark(2026).generate(),
                new SimulationConfig(20, ClockMode.REALTIME, 1e6, 0, Duration.ofSeconds(1), 1, BodyLimits.DEFAULT),
                2026, "bench", Recorder.NONE, List.of());
        Body body = new Body(0.5, 1.5, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(50, Math.toRadians(120)));
        for (int i = 0; i < 5; i++) {
            sim.connected(new NullSession(100_000 + i, Role.VIEWER));
        }
        List<NullSession> clients = new ArrayList<>();
        long[] seq = {0};
        for (int i = 0; i < agents; i++) {
            NullSession client = new NullSession(i + 1, Role.AGENT);
            clients.add(client);
            sim.connected(client);
            sim.received(client, new RegisterMessage(++seq[0], "A" + i, body, null));
            sim.received(client, new PerceptionRequestMessage(++seq[0], "A" + i, 0));
        }
        sim.applyNow();
        sim.start();
        SplittableRandom random = new SplittableRandom(2026);
        CpuRounds.run("load test's tick of " + agents + " agents", () -> {
            sim.beginTick();
            for (int i = 0; i < agents; i++) {
                NullSession client = clients.get(i);
                if (client.seen != null) {
                    Vec3 at = client.seen;
                    sim.received(client, new MoveMessage(++seq[0], "A" + i, at, Vec3.ground(
                            at.x() + random.nextDouble(-2, 2), at.z() + random.nextDouble(-2, 2))));
                    sim.received(client, new PerceptionRequestMessage(++seq[0], "A" + i, 0));
                    client.seen = null;
                }
            }
            sim.endTick();
            return seq[0];
        }, args.length > 1 ? Integer.parseInt(args[1]) : 400, args.length > 2 ? Integer.parseInt(args[2]) : 10,
                args.length > 3 ? Integer.parseInt(args[3]) : 50);
    }
}
