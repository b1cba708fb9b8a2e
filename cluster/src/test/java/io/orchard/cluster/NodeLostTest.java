package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * A node killed in the middle of a game (SIGKILL, three {@code orchard node} processes on loopback,
 * the paper's agents connected to all three, a cluster-wide checkpoint every second): the two others
 * take it for lost, the world rolls back to the last checkpoint, the lost node's parcels start again
 * on the survivors, every agent comes back with its resume token to a surviving node, and the game
 * goes on to its end from the checkpoint's tick, with nothing collected before the checkpoint lost.
 */
class NodeLostTest {

    private static final long SEED = 8;
    private static final int AGENTS = 10;
    private static final double SECONDS = 20;
    private static final Pattern ROLLED_BACK = Pattern.compile("was lost: the game goes on from its checkpoint of tick "
            + "(\\d+)");
    private static final Pattern PARCELS = Pattern.compile("parcels \\d+ \\[(.*)]");
    /** A health line of a node that hosts parcels. */
    private static final Pattern HOSTING = Pattern.compile("^node .* parcels [1-9]\\d* \\[");
    private static final MessageCodec CODEC = new MessageCodec();
    private static final JsonMapper JSON = JsonMapper.builder().build();

    @TempDir
    Path dir;

    @Test
    void aNodeKilledInTheMiddleOfAGameRollsTheWorldBackToItsCheckpointAndTheAgentsComeBack() throws Exception {
        Path recording = dir.resolve("cluster.ndjson");
        Path checkpoint = dir.resolve("game.json");
        Path tokens = dir.resolve("resume-tokens");
        try (NodeProcesses cluster = new NodeProcesses(NodeProcesses.lockstep(SEED, SECONDS, AGENTS, "--checkpoint",
                checkpoint.toString(), "--checkpoint-every", "1", "--record", recording.toString()))) {
            NodeProcesses.Node first = cluster.start(List.of());
            NodeProcesses.Node second = cluster.join();
            NodeProcesses.Node third = cluster.join();
            List<Integer> survivors = List.of(first.port(), second.port());
            ExecutorService threads = Executors.newFixedThreadPool(AGENTS);
            try {
                List<Future<GameOverMessage>> ends = new ArrayList<>();
                int i = 0;
                for (Species species : Species.values()) {
                    for (int n = 1; n <= AGENTS / Species.values().length; n++) {
                        String name = species.agentName() + n;
                        int port = List.of(first.port(), second.port(), third.port()).get(i++ % 3);
                        ends.add(threads.submit(() -> playThrough(species, name, tokens, port, survivors)));
                    }
                }
                awaitFruitEatenAndCheckpoint(checkpoint);
                third.await(HOSTING, 60); // its health line names parcels: on a quick machine, not yet the first
                Set<String> hosted = lastParcels(third);
                third.process().destroyForcibly();
                third.process().waitFor(60, TimeUnit.SECONDS);
                Matcher rolledBack = ROLLED_BACK.matcher(first.await(ROLLED_BACK, 180));
                assertThat(rolledBack.find()).isTrue();
                long from = Long.parseLong(rolledBack.group(1));
                for (Future<GameOverMessage> end : ends) {
                    assertThat(end.get(10, TimeUnit.MINUTES)).as("an agent's game ended").isNotNull();
                }
                check(Files.readAllLines(recording), from, AGENTS);
                Thread.sleep(6_000); // a health line of each survivor after the game
                Set<String> survived = new HashSet<>(lastParcels(first));
                survived.addAll(lastParcels(second));
                assertThat(hosted).as("the parcels the lost node hosted").isNotEmpty();
                assertThat(survived).as("the parcels on the survivors after the rollback").containsAll(hosted);
            } catch (AssertionError | java.util.concurrent.ExecutionException e) {
                throw new AssertionError(e.getMessage() + cluster.said(), e);
            } finally {
                threads.shutdownNow();
            }
        }
    }

    /**
     * Plays an agent to the end of the game: first at {@code port}, then, each time its connection
     * closes (its node was lost, or the world rolled back), again at a surviving node, with its resume
     * token.
     */
    static GameOverMessage playThrough(Species species, String name, Path tokens, int port,
                                               List<Integer> survivors) throws Exception {
        int at = port;
        for (int attempt = 0; attempt < 20; attempt++) {
            AgentController agent = species.create(name);
            agent.keepResumeTokensIn(tokens);
            try {
                return agent.run("127.0.0.1", at);
            } catch (IOException e) {
                at = survivors.get((attempt + name.length()) % survivors.size());
                Thread.sleep(500);
            }
        }
        throw new AssertionError(name + " could not get back into the game");
    }

    /** Waits until a fruit was eaten and a checkpoint written after it. */
    static void awaitFruitEatenAndCheckpoint(Path checkpoint) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(5);
        while (System.nanoTime() < deadline) {
            if (Files.exists(checkpoint)) {
                try {
                    for (JsonNode score : JSON.readTree(checkpoint.toFile()).get("scores")) {
                        if (score.get("points").asInt() > 0) {
                            return;
                        }
                    }
                } catch (RuntimeException e) {
                    // written as it is read: look again
                }
            }
            Thread.sleep(200);
        }
        throw new AssertionError("no fruit was eaten and saved within five minutes");
    }

    /**
     * The recording goes on after the rollback (the saved game's world opens it again, as a server's
     * resumed from a checkpoint) from the checkpoint's tick; the fruit collected before it stays
     * collected and its points stay scored; every agent registers again; the game ends with all of
     * them ranked.
     */
    static void check(List<String> all, long from, int agents) throws Exception {
        List<Message> lines = new ArrayList<>();
        for (String line : all) {
            JsonNode msg = JSON.readTree(line).get("msg");
            if (msg != null) {
                lines.add(CODEC.decode(msg.toString()));
            }
        }
        int restart = -1;
        for (int i = 1; i < lines.size(); i++) {
            if (lines.get(i) instanceof WorldSnapshotMessage) {
                restart = i;
            }
        }
        assertThat(restart).as("the saved game's world, where the recording goes on").isPositive();
        Map<String, Integer> collectedBefore = new HashMap<>();
        Set<String> eatenBefore = new HashSet<>();
        for (Message message : lines.subList(0, restart)) {
            if (message instanceof FruitEatenMessage eaten && eaten.tick() < from) {
                collectedBefore.merge(eaten.agent(), eaten.kind().points(), Integer::sum);
                eatenBefore.add(eaten.fruit());
            }
        }
        assertThat(eatenBefore).as("fruit collected before the checkpoint").isNotEmpty();
        WorldSnapshotMessage first = (WorldSnapshotMessage) lines.get(0);
        WorldSnapshotMessage restored = (WorldSnapshotMessage) lines.get(restart);
        assertThat(restored.fruit()).as("the world after the rollback")
                .noneMatch(fruit -> eatenBefore.contains(fruit.id()))
                .hasSize(first.fruit().size() - eatenBefore.size());
        Set<String> back = new HashSet<>();
        Long firstTick = null;
        GameOverMessage over = null;
        for (Message message : lines.subList(restart, lines.size())) {
            if (message instanceof RegisteredMessage registered) {
                back.add(registered.agent());
            } else if (message instanceof TickMessage tick && firstTick == null) {
                firstTick = tick.tick();
            } else if (message instanceof GameOverMessage end) {
                over = end;
            }
        }
        assertThat(firstTick).as("the first tick after the rollback").isEqualTo(from);
        assertThat(back).as("the agents that came back").hasSize(agents);
        assertThat(over).as("the game's end").isNotNull();
        assertThat(over.ranking()).as("the final ranking").hasSize(agents);
        Map<String, Integer> points = new HashMap<>();
        over.ranking().forEach(score -> points.put(score.agent(), score.points()));
        collectedBefore.forEach((agent, before) -> assertThat(points.get(agent))
                .as("%s's points at the end, with those it scored before the checkpoint", agent)
                .isGreaterThanOrEqualTo(before));
    }

    /** The parcels the node hosted as its last health line said. */
    static Set<String> lastParcels(NodeProcesses.Node node) {
        Set<String> parcels = new HashSet<>();
        for (String line : node.said()) {
            Matcher matcher = PARCELS.matcher(line);
            if (line.startsWith("node ") && matcher.find()) {
                parcels.clear();
                Matcher each = Pattern.compile("\\d+,\\d+").matcher(matcher.group(1));
                while (each.find()) {
                    parcels.add(each.group());
                }
            }
        }
        return parcels;
    }
}
