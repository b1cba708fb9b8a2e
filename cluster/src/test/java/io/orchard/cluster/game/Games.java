package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.FileRecorder;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.WorldOptions;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.SplittableRandom;
import java.util.function.Function;

/** Test games of deterministic agents, played on the single server's simulation and split into parcels. */
final class Games {

    static final long SEED = 1998;

    private Games() {}

    /** One game, stepped as its owner thread would. */
    interface Game {
        void connected(ClientSession session);

        void received(ClientSession session, ClientMessage message);

        void disconnected(ClientSession session, String reason);

        void applyNow();

        void beginTick();

        void endTick();

        Phase phase();

        long tick();
    }

    /** The paper's garden of the seed, with 200 fruit: agents reach for fruit in every parcel. */
    static World world() {
        return new WorldGenerator(new SplittableRandom(SEED), WorldOptions.DEFAULT.withFruit(200)).generate();
    }

    /** A lockstep game of {@code seconds} that starts when {@code agents} have come. */
    static SimulationConfig lockstep(int agents, double seconds) {
        return new SimulationConfig(20, ClockMode.LOCKSTEP, seconds, agents, Duration.ofSeconds(2), 8,
                BodyLimits.DEFAULT);
    }

    /** {@code count} foragers, connecting in an order that {@code order} shuffles. */
    static List<Player> foragers(int count, long order) {
        List<Integer> numbers = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            numbers.add(i);
        }
        Collections.shuffle(numbers, new Random(order));
        List<Player> agents = new ArrayList<>();
        long id = 0;
        for (int i : numbers) {
            // Sights of 20 to 50 units: parcels of 25 see well beyond their neighbours.
            agents.add(new Forager("Forager" + (char) ('A' + i % 26) + i, new TestSession(++id, Role.AGENT),
                    20 + i % 4 * 10));
        }
        return agents;
    }

    /** Plays the game to its end. */
    static void play(Game game, List<Player> agents) {
        play(game, agents, tick -> { });
    }

    /** Plays the game to its end, telling {@code between} each tick that ended, before the next begins. */
    static void play(Game game, List<Player> agents, java.util.function.LongConsumer between) {
        agents.forEach(agent -> game.connected(agent.session()));
        game.applyNow();
        send(game, agents, Player::register);
        game.applyNow();
        send(game, agents, Player::setUp);
        game.applyNow();
        assertThat(game.phase()).as("the game started").isEqualTo(Phase.RUNNING);
        while (game.phase() == Phase.RUNNING) {
            game.beginTick();
            long tick = game.tick();
            for (Player agent : agents) {
                agent.act(tick).forEach(message -> game.received(agent.session(), message));
            }
            game.endTick();
            between.accept(tick);
        }
    }

    private static void send(Game game, List<Player> agents, Function<Player, List<ClientMessage>> what) {
        for (Player agent : agents) {
            what.apply(agent).forEach(message -> game.received(agent.session(), message));
        }
    }

    /** Plays {@code agents} on the single server's simulation; returns the recording, in {@code dir}. */
    static Path single(Path dir, World world, SimulationConfig config, Placement placement, List<Player> agents)
            throws Exception {
        Path recording = dir.resolve("single.ndjson");
        try (FileRecorder recorder = FileRecorder.open(recording)) {
            Simulation simulation = new Simulation(world, config, SEED, "test", recorder, List.of(), placement);
            play(of(simulation), agents);
            simulation.stopped();
        }
        return recording;
    }

    /** The single server's simulation, stepped as a game. */
    static Game of(Simulation simulation) {
        return new Game() {
            public void connected(ClientSession s) { simulation.connected(s); }
            public void received(ClientSession s, ClientMessage m) { simulation.received(s, m); }
            public void disconnected(ClientSession s, String r) { simulation.disconnected(s, r); }
            public void applyNow() { simulation.applyNow(); }
            public void beginTick() { simulation.beginTick(); }
            public void endTick() { simulation.endTick(); }
            public Phase phase() { return simulation.phase(); }
            public long tick() { return simulation.tick(); }
        };
    }

    /** A split game, stepped as a game. */
    static Game of(SplitGame split) {
        return new Game() {
            public void connected(ClientSession s) { split.connected(s); }
            public void received(ClientSession s, ClientMessage m) { split.received(s, m); }
            public void disconnected(ClientSession s, String r) { split.disconnected(s, r); }
            public void applyNow() { split.applyNow(); }
            public void beginTick() { split.beginTick(); }
            public void endTick() { split.endTick(); }
            public Phase phase() { return split.phase(); }
            public long tick() { return split.tick(); }
        };
    }

    /**
     * Plays {@code agents} on a game cut into parcels of 25 units, which {@code parcels} makes; its
     * recording goes to {@code split.ndjson} in {@code dir}. Returns its counts.
     */
    static SplitCounts split(Path dir, World world, SimulationConfig config, Placement placement, List<Player> agents,
                             Function<ParcelGrid, Parcels> parcels) throws Exception {
        return split(dir, world, config, placement, agents, parcels, tick -> { });
    }

    /** As {@link #split}, telling {@code between} each tick that ended. */
    static SplitCounts split(Path dir, World world, SimulationConfig config, Placement placement, List<Player> agents,
                             Function<ParcelGrid, Parcels> parcels, java.util.function.LongConsumer between)
            throws Exception {
        try (FileRecorder recorder = FileRecorder.open(dir.resolve("split.ndjson"))) {
            SplitGame split = new SplitGame(world, config, SEED, "test", recorder, List.of(), 25, placement, parcels);
            play(of(split), agents, between);
            return split.counts();
        }
    }

    /** The split game's recording and the single's, line by line (to name the first that differs), then byte for byte. */
    static void sameRecordings(Path dir, Path single) throws Exception {
        Path parcels = dir.resolve("split.ndjson");
        List<String> expected = Files.readAllLines(single);
        List<String> actual = Files.readAllLines(parcels);
        for (int i = 0; i < Math.min(expected.size(), actual.size()); i++) {
            assertThat(actual.get(i)).as("line %d of the split game's recording", i + 1).isEqualTo(expected.get(i));
        }
        assertThat(Files.readAllBytes(parcels)).as("the split game's recording, byte for byte")
                .isEqualTo(Files.readAllBytes(single));
    }
}
