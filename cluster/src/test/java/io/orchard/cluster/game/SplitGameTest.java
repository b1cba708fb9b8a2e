package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
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
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.SplittableRandom;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same lockstep game of 30 deterministic agents, played by the single server's simulation and by
 * a game whose world is cut into parcels of 25 units (64 of them), connected in another order: the
 * two recordings are the same file, byte for byte, and in the split game agents walked from parcel
 * to parcel, saw agents in other parcels, grasped fruit in other parcels and walked paths beyond
 * their parcels' halos.
 */
class SplitGameTest {

    private static final long SEED = 1998;
    private static final int AGENTS = 30;
    private static final SimulationConfig CONFIG = new SimulationConfig(20, ClockMode.LOCKSTEP, 60, AGENTS,
            Duration.ofSeconds(2), 8, BodyLimits.DEFAULT);

    @TempDir
    Path dir;

    /** One of the two games, stepped as its owner thread would. */
    private interface Game {
        void connected(ClientSession session);

        void received(ClientSession session, ClientMessage message);

        void applyNow();

        void beginTick();

        void endTick();

        Phase phase();

        long tick();
    }

    private static World world() {
        return new WorldGenerator(new SplittableRandom(SEED), WorldOptions.DEFAULT.withFruit(200)).generate();
    }

    /** Thirty foragers, connecting in an order that {@code order} shuffles. */
    private static List<Player> foragers(long order) {
        List<Integer> numbers = new ArrayList<>();
        for (int i = 0; i < AGENTS; i++) {
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
    private static void play(Game game, List<Player> agents) {
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
        }
    }

    private static void send(Game game, List<Player> agents, Function<Player, List<ClientMessage>> what) {
        for (Player agent : agents) {
            what.apply(agent).forEach(message -> game.received(agent.session(), message));
        }
    }

    /** Plays {@code agents} on the single server's simulation; returns the recording. */
    private Path single(World world, SimulationConfig config, Placement placement, List<Player> agents)
            throws Exception {
        Path recording = dir.resolve("single.ndjson");
        try (FileRecorder recorder = FileRecorder.open(recording)) {
            Simulation simulation = new Simulation(world, config, SEED, "test", recorder, List.of(), placement);
            play(new Game() {
                public void connected(ClientSession s) { simulation.connected(s); }
                public void received(ClientSession s, ClientMessage m) { simulation.received(s, m); }
                public void applyNow() { simulation.applyNow(); }
                public void beginTick() { simulation.beginTick(); }
                public void endTick() { simulation.endTick(); }
                public Phase phase() { return simulation.phase(); }
                public long tick() { return simulation.tick(); }
            }, agents);
            simulation.stopped();
        }
        return recording;
    }

    /** Plays {@code agents} on a game cut into parcels of 25 units; returns its counts. */
    private SplitCounts split(World world, SimulationConfig config, Placement placement, List<Player> agents)
            throws Exception {
        try (FileRecorder recorder = FileRecorder.open(dir.resolve("split.ndjson"))) {
            SplitGame split = new SplitGame(world, config, SEED, "test", recorder, List.of(), 25, placement);
            play(new Game() {
                public void connected(ClientSession s) { split.connected(s); }
                public void received(ClientSession s, ClientMessage m) { split.received(s, m); }
                public void applyNow() { split.applyNow(); }
                public void beginTick() { split.beginTick(); }
                public void endTick() { split.endTick(); }
                public Phase phase() { return split.phase(); }
                public long tick() { return split.tick(); }
            }, agents);
            return split.counts();
        }
    }

    /** The two recordings, line by line (to name the first that differs), then byte for byte. */
    private void sameRecordings(Path single) throws Exception {
        Path parcels = dir.resolve("split.ndjson");
        List<String> expected = Files.readAllLines(single);
        List<String> actual = Files.readAllLines(parcels);
        for (int i = 0; i < Math.min(expected.size(), actual.size()); i++) {
            assertThat(actual.get(i)).as("line %d of the split game's recording", i + 1).isEqualTo(expected.get(i));
        }
        assertThat(Files.readAllBytes(parcels)).as("the split game's recording, byte for byte")
                .isEqualTo(Files.readAllBytes(single));
    }

    @Test
    void aGameCutIntoParcelsIsTheSingleServersGameByteForByte() throws Exception {
        Placement anywhere = (name, radius) -> null;
        Path single = single(world(), CONFIG, anywhere, foragers(1));
        SplitCounts counts = split(world(), CONFIG, anywhere, foragers(2));
        String text = Files.readString(single, StandardCharsets.UTF_8);
        System.out.printf("recording of %d bytes; %s%n", text.length(), counts);
        assertThat(text).as("the game was played").contains("\"type\":\"FruitEaten\"", "\"type\":\"GameOver\"")
                .doesNotContain("\"dir\":\"missed\"");
        sameRecordings(single);
        assertThat(counts.handOvers()).as("agents walked from parcel to parcel").isPositive();
        assertThat(counts.sightingsAcrossBorders()).as("agents saw agents in other parcels").isPositive();
        assertThat(counts.graspsAcrossBorders()).as("agents grasped fruit in other parcels").isPositive();
        assertThat(counts.pathsBeyondHalo()).as("paths left their parcels' halos").isPositive();
    }

    /**
     * Eight agents that meet again and again where four parcels' corners touch, bumping into each
     * other across the borders: those that could touch are walked together, and the game is still
     * the single server's, stop for stop.
     */
    @Test
    void agentsThatBumpIntoEachOtherAcrossBordersAreWalkedAsOnOneServer() throws Exception {
        World world = world();
        Vec3 corner = freeCorner(world);
        SimulationConfig config = new SimulationConfig(20, ClockMode.LOCKSTEP, 15, 8, Duration.ofSeconds(2), 8,
                BodyLimits.DEFAULT);
        Placement ring = (name, radius) -> {
            double angle = (name.charAt(name.length() - 1) - '0') * Math.PI / 4;
            return Vec3.ground(corner.x() + 3 * Math.cos(angle), corner.z() + 3 * Math.sin(angle));
        };
        Path single = single(world, config, ring, crowders(corner));
        SplitCounts counts = split(world(), config, ring, crowders(corner));
        assertThat(Files.readString(single)).as("agents stopped when they met").contains("\"duration\":0.0");
        sameRecordings(single);
        assertThat(counts.walkedTogether()).as("agents walked together across borders").isPositive();
    }

    private static List<Player> crowders(Vec3 meeting) {
        List<Player> agents = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            agents.add(new Crowder("Crowder" + i, new TestSession(i + 1, Role.AGENT), meeting));
        }
        return agents;
    }

    /** A point where four parcels of 25 meet, with room around it for a ring of eight agents. */
    private static Vec3 freeCorner(World world) {
        for (int x = -75; x <= 75; x += 25) {
            for (int z = -75; z <= 75; z += 25) {
                if (world.checkPlace(new Point2(x, z), 4).isFree()) {
                    return Vec3.ground(x, z);
                }
            }
        }
        throw new AssertionError("no free corner in the world");
    }
}
