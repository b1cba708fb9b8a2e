package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A node process asked to stop (SIGTERM, as Ctrl-C does) in the middle of a lockstep game, three
 * {@code orchard node} processes on loopback, the paper's agents connected to the two others: the
 * node leaves the cluster, its parcels are handed over with their state to the nodes that stay,
 * nothing is rolled back, and the game's recording is one server's, byte for byte.
 */
class NodeLeavesTest {

    private static final long SEED = 8;
    private static final int AGENTS = 10;
    private static final double SECONDS = 30;
    /** A health line of a node that hosts parcels. */
    private static final Pattern HOSTING = Pattern.compile("^node .* parcels [1-9]\\d* \\[");
    private static final Pattern ALL_UP = Pattern.compile("^node \\S+ +members up 3 ");
    private static final Pattern TAKEN_UP = Pattern.compile("parcel \\d+,\\d+ taken up here");
    private static final Pattern LOST = Pattern.compile("was lost|UNREACHABLE|SBR took decision");

    @TempDir
    Path dir;

    static List<AgentController> agents() {
        List<AgentController> agents = new ArrayList<>();
        for (int i = 1; i <= AGENTS / Species.values().length; i++) {
            for (Species species : Species.values()) {
                agents.add(species.create(species.agentName() + i));
            }
        }
        return agents;
    }

    static List<Future<GameOverMessage>> play(ExecutorService threads, List<Integer> ports) {
        List<Future<GameOverMessage>> ends = new ArrayList<>();
        List<AgentController> agents = agents();
        for (int i = 0; i < agents.size(); i++) {
            AgentController agent = agents.get(i);
            int port = ports.get(i % ports.size());
            ends.add(threads.submit(() -> agent.run("127.0.0.1", port)));
        }
        return ends;
    }

    static void awaitEnds(List<Future<GameOverMessage>> ends) throws Exception {
        for (Future<GameOverMessage> end : ends) {
            assertThat(end.get(10, TimeUnit.MINUTES)).as("an agent's game ended").isNotNull();
        }
    }

    @Test
    void aNodeSentSigtermInTheMiddleOfAGameHandsItsParcelsOverAndNothingIsLost() throws Exception {
        Path single = dir.resolve("server.ndjson");
        ExecutorService threads = Executors.newFixedThreadPool(AGENTS);
        try {
            try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                    .timeLimit(SECONDS).waitFor(AGENTS).lockstepDeadline(Duration.ofSeconds(20)).record(single)
                    .start()) {
                awaitEnds(play(threads, List.of(server.port())));
                server.gameOver().get(1, TimeUnit.MINUTES);
            }
            Path recording = dir.resolve("cluster.ndjson");
            try (NodeProcesses cluster = new NodeProcesses(NodeProcesses.lockstep(SEED, SECONDS, AGENTS, "--record",
                    recording.toString()))) {
                NodeProcesses.Node first = cluster.start(List.of());
                NodeProcesses.Node second = cluster.join();
                NodeProcesses.Node third = cluster.join();
                try {
                    // All three up before the game starts: its parcels are placed on all three at its
                    // start, and none moves to a node that joins while it runs.
                    first.await(ALL_UP, 120);
                    List<Future<GameOverMessage>> ends = play(threads, List.of(first.port(), second.port()));
                    third.await(HOSTING, 120);
                    first.awaitTick(1, 120);
                    // SIGTERM, as Process.destroy() sends, but through the handle, which leaves the
                    // node's output open to be read as it leaves.
                    assertThat(third.process().toHandle().destroy()).as("SIGTERM sent").isTrue();
                    assertThat(third.process().waitFor(90, TimeUnit.SECONDS)).as("the node stopped").isTrue();
                    assertThat(Files.readString(recording)).as("the game was under way when the node left")
                            .doesNotContain("\"type\":\"GameOver\"");
                    awaitEnds(ends);
                    assertThat(third.said()).as("what the node that left said")
                            .anyMatch(line -> line.contains("leaving the cluster"));
                    List<String> stayed = new ArrayList<>(first.said());
                    stayed.addAll(second.said());
                    assertThat(stayed).as("the parcels taken up by the nodes that stayed")
                            .anyMatch(line -> TAKEN_UP.matcher(line).find());
                    assertThat(stayed).as("the nodes that stayed never took the node for lost")
                            .noneMatch(line -> LOST.matcher(line).find());
                } catch (AssertionError | java.util.concurrent.ExecutionException e) {
                    throw new AssertionError(e.getMessage() + cluster.said(), e);
                }
            }
            assertThat(NodeProcessesTest.firstDifferentLine(single, recording))
                    .as("the first line where the cluster's recording differs from the server's").isEmpty();
            assertThat(Files.mismatch(single, recording)).as("the cluster's recording, byte for byte")
                    .isEqualTo(-1L);
        } finally {
            threads.shutdownNow();
        }
    }
}
