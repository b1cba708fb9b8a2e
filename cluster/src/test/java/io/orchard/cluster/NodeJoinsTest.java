package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.WorldOptions;
import io.orchard.server.world.scenario.ScenarioFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A node process that joins a cluster of two in the middle of a lockstep game, the paper's agents
 * connected to the two first: Pekko moves parcels onto it (its rebalancing), each with what it holds,
 * while the game runs, and the game's recording is one server's, byte for byte.
 */
class NodeJoinsTest {

    private static final long SEED = 8;
    private static final int AGENTS = 10;
    private static final double SECONDS = 60;
    private static final int FRUIT = 150;
    /** The tick's node kept a parcel's state as Pekko moved it (onto the node that joined: it has none). */
    private static final Pattern KEPT = Pattern.compile("parcel \\d+,\\d+ kept while it moves to another node");
    private static final Pattern LOST = Pattern.compile("was lost|UNREACHABLE|SBR took decision");

    @TempDir
    Path dir;

    @Test
    void aNodeThatJoinsInTheMiddleOfAGameTakesParcelsOverAndNothingIsLost() throws Exception {
        // More fruit than the paper's 30, so that the game does not end, all fruit collected, before
        // Pekko moves parcels (a few every 10 s) onto the node that joins.
        Path world = dir.resolve("world.json");
        ScenarioFile.write(new WorldGenerator(new SplittableRandom(SEED), WorldOptions.DEFAULT.withFruit(FRUIT))
                .scenario(), world);
        Path single = dir.resolve("server.ndjson");
        ExecutorService threads = Executors.newFixedThreadPool(AGENTS);
        try {
            try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                    .timeLimit(SECONDS).waitFor(AGENTS).lockstepDeadline(Duration.ofSeconds(20)).record(single)
                    .scenario(world).start()) {
                NodeLeavesTest.awaitEnds(NodeLeavesTest.play(threads, List.of(server.port())));
                server.gameOver().get(1, TimeUnit.MINUTES);
            }
            Path recording = dir.resolve("cluster.ndjson");
            try (NodeProcesses cluster = new NodeProcesses(NodeProcesses.lockstep(SEED, SECONDS, AGENTS, "--scenario",
                    world.toString(), "--record", recording.toString()))) {
                NodeProcesses.Node first = cluster.start(List.of());
                NodeProcesses.Node second = cluster.join();
                try {
                    List<Future<GameOverMessage>> ends = NodeLeavesTest.play(threads,
                            List.of(first.port(), second.port()));
                    first.awaitTick(1, 120);
                    NodeProcesses.Node third = cluster.join();
                    // A parcel moved to the new node starts there when the tick next asks it a step,
                    // which it does only while the parcel has agents: the hand-off is what shows.
                    first.await(KEPT, 120);
                    assertThat(Files.readString(recording)).as("the game was under way when parcels moved")
                            .doesNotContain("\"type\":\"GameOver\"");
                    NodeLeavesTest.awaitEnds(ends);
                    List<String> all = new ArrayList<>(first.said());
                    all.addAll(second.said());
                    all.addAll(third.said());
                    assertThat(all).as("no node was taken for lost").noneMatch(line -> LOST.matcher(line).find());
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
