package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.zoo.Species;
import io.orchard.protocol.message.GameOverMessage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The node that runs the tick asked to stop (SIGTERM) in the middle of a lockstep game, three
 * {@code orchard node} processes on loopback, the paper's agents connected to the two others: the
 * node saves the game as it leaves, the tick starts on the next oldest node and goes on from that
 * save, the agents come back with their resume tokens, and the game ends with nothing collected lost
 * and no node taken for lost.
 */
class TickLeavesTest {

    private static final long SEED = 8;
    private static final int AGENTS = 10;
    private static final double SECONDS = 20;
    private static final Pattern ALL_UP = Pattern.compile("^node \\S+ +members up 3 ");
    private static final Pattern GOES_ON = Pattern.compile("the node that ran the tick left the cluster: the game "
            + "goes on from its checkpoint of tick (\\d+)");
    private static final Pattern HEALTH = Pattern.compile("^node \\S+ +members up");
    private static final Pattern OVER = Pattern.compile("the game is over at tick");
    private static final Pattern CAME_AFTER_THE_END = Pattern.compile("the tick came to this node after the game was "
            + "over");
    private static final Pattern LOST = Pattern.compile("was lost|UNREACHABLE|SBR took decision");

    @TempDir
    Path dir;

    @Test
    void theTicksNodeLeavingMidGameMovesTheTickAndTheGameGoesOnFromWhereItWas() throws Exception {
        Path recording = dir.resolve("cluster.ndjson");
        Path checkpoint = dir.resolve("game.json");
        Path tokens = dir.resolve("resume-tokens");
        try (NodeProcesses cluster = new NodeProcesses(NodeProcesses.lockstep(SEED, SECONDS, AGENTS, "--checkpoint",
                checkpoint.toString(), "--checkpoint-every", "1", "--record", recording.toString()))) {
            NodeProcesses.Node first = cluster.start(List.of());
            NodeProcesses.Node second = cluster.join();
            NodeProcesses.Node third = cluster.join();
            List<Integer> staying = List.of(second.port(), third.port());
            ExecutorService threads = Executors.newFixedThreadPool(AGENTS);
            try {
                first.await(ALL_UP, 120);
                List<Future<GameOverMessage>> ends = new ArrayList<>();
                int i = 0;
                for (Species species : Species.values()) {
                    for (int n = 1; n <= AGENTS / Species.values().length; n++) {
                        String name = species.agentName() + n;
                        int port = staying.get(i++ % 2);
                        ends.add(threads.submit(() -> NodeLostTest.playThrough(species, name, tokens, port, staying)));
                    }
                }
                NodeLostTest.awaitFruitEatenAndCheckpoint(checkpoint);
                // The first node is the oldest, where Pekko runs the tick, the cluster singleton.
                assertThat(first.process().toHandle().destroy()).as("SIGTERM sent").isTrue();
                assertThat(first.process().waitFor(90, TimeUnit.SECONDS)).as("the node stopped").isTrue();
                assertThat(first.said()).as("what the tick's node said").anyMatch(line -> line.contains(
                        "leaving the cluster"));
                Matcher from = GOES_ON.matcher(awaitEither(second, third));
                assertThat(from.find()).isTrue();
                for (Future<GameOverMessage> end : ends) {
                    assertThat(end.get(10, TimeUnit.MINUTES)).as("an agent's game ended").isNotNull();
                }
                NodeLostTest.check(Files.readAllLines(recording), Long.parseLong(from.group(1)), AGENTS);
                List<String> stayed = new ArrayList<>(second.said());
                stayed.addAll(third.said());
                assertThat(stayed).as("the nodes that stayed never took a node for lost")
                        .noneMatch(line -> LOST.matcher(line).find());
            } catch (AssertionError | java.util.concurrent.ExecutionException e) {
                throw new AssertionError(e.getMessage() + cluster.said(), e);
            } finally {
                threads.shutdownNow();
            }
        }
    }

    @Test
    void theTicksNodeStoppedAfterTheGameLeavesItsRecordingWhole() throws Exception {
        Path recording = dir.resolve("over.ndjson");
        ExecutorService threads = Executors.newFixedThreadPool(AGENTS);
        try (NodeProcesses cluster = new NodeProcesses(NodeProcesses.lockstep(SEED, 3, AGENTS, "--record",
                recording.toString()))) {
            NodeProcesses.Node first = cluster.start(List.of());
            NodeProcesses.Node second = cluster.join();
            try {
                NodeLeavesTest.awaitEnds(NodeLeavesTest.play(threads, List.of(first.port(), second.port())));
                first.await(OVER, 60);
                byte[] played = Files.readAllBytes(recording);
                assertThat(new String(played, java.nio.charset.StandardCharsets.UTF_8)).contains("\"type\":\"GameOver\"");
                assertThat(first.process().toHandle().destroy()).as("SIGTERM sent").isTrue();
                second.await(CAME_AFTER_THE_END, 180);
                second.await(HEALTH, 30); // said after the tick's start there, which would open the recording
                assertThat(Files.readAllBytes(recording)).as("the recording, after the tick moved to the other node")
                        .isEqualTo(played);
            } catch (AssertionError | java.util.concurrent.ExecutionException e) {
                throw new AssertionError(e.getMessage() + cluster.said(), e);
            }
        } finally {
            threads.shutdownNow();
        }
    }

    /** The line of whichever of the two nodes took up the tick and said the game goes on. */
    private static String awaitEither(NodeProcesses.Node one, NodeProcesses.Node other) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(3);
        while (System.nanoTime() < deadline) {
            for (NodeProcesses.Node node : List.of(one, other)) {
                for (String line : node.said()) {
                    if (GOES_ON.matcher(line).find()) {
                        return line;
                    }
                }
            }
            Thread.sleep(200);
        }
        throw new AssertionError("no node said the game goes on within 3 minutes");
    }
}
