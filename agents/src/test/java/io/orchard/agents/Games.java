package io.orchard.agents;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.Placement;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Plays games for tests: a real server in lockstep mode on port 0 with a fixed seed, the agents
 * each on its own connection and thread, until the game is over. The agents join one after the
 * other, so that a seed gives the same game every time.
 */
public final class Games {

    /** What a game gave. */
    public record Result(long seed, int fruitAtStart, int fruitEaten, GameOverMessage over, List<AgentController> agents,
                         double wallSeconds) {

        /** The agent of that name. */
        public AgentController agent(String name) {
            return agents.stream().filter(a -> a.name().equals(name)).findFirst().orElseThrow();
        }
    }

    private Games() {}

    /** Plays a lockstep game of {@code seed} lasting {@code timeLimit} simulated seconds. */
    public static Result play(long seed, double timeLimit, List<? extends AgentController> agents) throws Exception {
        return play(seed, timeLimit, agents, (name, radius) -> null);
    }

    /** As {@link #play(long, double, List)}, placing the agents with {@code placement}. */
    public static Result play(long seed, double timeLimit, List<? extends AgentController> agents, Placement placement)
            throws Exception {
        return play(seed, timeLimit, agents, placement, new GameListener() { });
    }

    /** As {@link #play(long, double, List, Placement)}, with {@code listener} hearing the game on the server's thread. */
    public static Result play(long seed, double timeLimit, List<? extends AgentController> agents, Placement placement,
                              GameListener listener) throws Exception {
        return play(seed, timeLimit, agents, placement, listener, null);
    }

    /**
     * As {@link #play(long, double, List)}, the server recording the game to {@code recording} (as
     * {@code --record} does) with a viewer connected before the agents join, so that the recording
     * starts with the world's snapshot.
     */
    public static Result recorded(long seed, double timeLimit, List<? extends AgentController> agents, Path recording)
            throws Exception {
        return play(seed, timeLimit, agents, (name, radius) -> null, new GameListener() { }, recording);
    }

    /** As {@link #recorded(long, double, List, Path)}, placing the agents and with a listener of the game. */
    public static Result recorded(long seed, double timeLimit, List<? extends AgentController> agents,
                                  Placement placement, GameListener listener, Path recording) throws Exception {
        return play(seed, timeLimit, agents, placement, listener, recording);
    }

    private static Result play(long seed, double timeLimit, List<? extends AgentController> agents, Placement placement,
                               GameListener listener, @Nullable Path recording) throws Exception {
        AtomicInteger eaten = new AtomicInteger();
        AtomicInteger total = new AtomicInteger();
        BlockingQueue<String> joined = new LinkedBlockingQueue<>();
        WorldServer.Builder builder = WorldServer.builder();
        if (recording != null) {
            builder.record(recording);
        }
        try (WorldServer server = builder.port(0).seed(seed).clock(ClockMode.LOCKSTEP)
                .timeLimit(timeLimit).waitFor(agents.size()).placement(placement).listener(listener)
                .listener(new GameListener() {
                    @Override
                    public void gameStarted(long s, int fruitCount, double limit) {
                        total.set(fruitCount);
                    }

                    @Override
                    public void fruitEaten(String agent, String fruit, FruitKind kind, double time) {
                        eaten.incrementAndGet();
                    }

                    @Override
                    public void agentJoined(String agent) {
                        joined.add(agent);
                    }
                }).start();
             AutoCloseable viewer = recording == null ? () -> { } : watch(server)) {
            ExecutorService pool = Executors.newFixedThreadPool(agents.size());
            try {
                long start = System.nanoTime();
                List<Future<GameOverMessage>> runs = new ArrayList<>();
                for (AgentController agent : agents) {
                    // One at a time, so that the server orders the clients the same way in every run.
                    runs.add(pool.submit(() -> agent.run("127.0.0.1", server.port())));
                    if (joined.poll(30, TimeUnit.SECONDS) == null) {
                        throw new IllegalStateException(agent.name() + " did not join the game within 30 s");
                    }
                }
                GameOverMessage over = null;
                for (Future<GameOverMessage> run : runs) {
                    over = run.get(150, TimeUnit.SECONDS);
                }
                return new Result(seed, total.get(), eaten.get(), over, List.copyOf(agents),
                        (System.nanoTime() - start) / 1e9);
            } finally {
                agents.forEach(AgentController::stop);
                pool.shutdownNow();
            }
        }
    }

    /** A viewer on the server, connected once it has the world's snapshot. */
    private static ProtocolConnection watch(WorldServer server) throws Exception {
        CompletableFuture<WorldSnapshotMessage> snapshot = new CompletableFuture<>();
        ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "games-viewer",
                message -> {
                    if (message instanceof WorldSnapshotMessage world) {
                        snapshot.complete(world);
                    }
                });
        snapshot.get(30, TimeUnit.SECONDS);
        return viewer;
    }

    /** The fruit of the world of {@code seed}, as the server generates it. */
    public static List<FruitState> fruitOf(long seed) {
        return WorldGenerator.standard(seed).scenario().fruit();
    }

    /**
     * A start and a goal {@code length} units north of it in the world of {@code seed}, both free
     * for a body of radius 0.5 and joined by a free straight walk: for telling an agent where to go.
     */
    public static Point2[] freeWalk(long seed, double length) {
        World world = WorldGenerator.standard(seed).generate();
        for (int ring = 0; ring < 40; ring++) {
            for (int k = 0; k < Math.max(1, ring * 8); k++) {
                double angle = k * 2 * Math.PI / Math.max(1, ring * 8);
                Point2 start = new Point2(Math.round(-27 + 2 * ring * Math.cos(angle)),
                        Math.round(40 + 2 * ring * Math.sin(angle)));
                Point2 goal = new Point2(start.x(), start.z() + length);
                if (world.checkPlace(start, 1).isFree() && world.checkPlace(goal, 1).isFree()
                        && world.checkMove(start, goal, 1).isFree()) {
                    return new Point2[] {start, goal};
                }
            }
        }
        throw new IllegalStateException("no free walk of " + length + " units in the world of seed " + seed);
    }

    /** A placement that puts the named agents at fixed points (the others where the seed puts them). */
    public static Placement at(Map<String, Vec3> places) {
        return (name, radius) -> places.get(name);
    }
}
