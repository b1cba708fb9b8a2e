package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.IntUnaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The paper's agents, two of each kind, play a lockstep game on one world server, and the same game
 * on a cluster of three nodes in this JVM (three Pekko actor systems on loopback ports, each with a
 * gateway on a TCP port of its own), each agent connected over a real socket to a node of its own
 * choosing: the cluster's recording is the server's, byte for byte.
 */
class ClusterNodesTest {

    private static final long SEED = 8;
    private static final double SECONDS = 20;

    @TempDir
    Path dir;

    private static List<AgentController> agents() {
        List<AgentController> agents = new ArrayList<>();
        for (Species species : Species.values()) {
            for (int i = 1; i <= 2; i++) {
                agents.add(species.create(species.agentName() + i));
            }
        }
        return agents;
    }

    /** Runs every agent on a thread of its own, the i-th connecting to {@code portOf(i)}; waits for their ends. */
    private static void play(List<AgentController> agents, IntUnaryOperator portOf) throws Exception {
        ExecutorService threads = Executors.newFixedThreadPool(agents.size());
        try {
            List<Future<GameOverMessage>> ends = new ArrayList<>();
            for (int i = 0; i < agents.size(); i++) {
                AgentController agent = agents.get(i);
                int port = portOf.applyAsInt(i);
                ends.add(threads.submit(() -> agent.run("127.0.0.1", port)));
            }
            for (Future<GameOverMessage> end : ends) {
                assertThat(end.get(10, TimeUnit.MINUTES)).as("the agent's game ended").isNotNull();
            }
        } finally {
            threads.shutdownNow();
        }
    }

    @Test
    void threeNodesServeTheGameOneServerServesByteForByte() throws Exception {
        Path single = dir.resolve("server.ndjson");
        List<AgentController> onServer = agents();
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(SECONDS).waitFor(onServer.size()).lockstepDeadline(Duration.ofSeconds(20))
                .record(single).start()) {
            play(onServer, i -> server.port());
            server.gameOver().get(1, TimeUnit.MINUTES);
        }

        Path cluster = dir.resolve("cluster.ndjson");
        List<ClusterNode> nodes = new ArrayList<>();
        try {
            ClusterNode first = node(List.of()).record(cluster).start();
            nodes.add(first);
            for (int i = 0; i < 2; i++) {
                nodes.add(node(List.of("127.0.0.1:" + first.clusterPort())).start());
            }
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (first.membersUp() < 3 && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
            assertThat(first.membersUp()).as("the three nodes are up").isEqualTo(3);
            List<AgentController> onCluster = agents();
            Collections.reverse(onCluster); // another order of connecting
            play(onCluster, i -> nodes.get(i % nodes.size()).port());
        } finally {
            Collections.reverse(nodes);
            nodes.forEach(ClusterNode::close);
        }

        String recorded = Files.readString(single, StandardCharsets.UTF_8);
        assertThat(recorded).as("no turn was missed").doesNotContain("\"dir\":\"missed\"")
                .contains("\"type\":\"GameOver\"");
        List<String> expected = Files.readAllLines(single);
        List<String> actual = Files.readAllLines(cluster);
        for (int i = 0; i < Math.min(expected.size(), actual.size()); i++) {
            assertThat(actual.get(i)).as("line %d of the cluster's recording", i + 1).isEqualTo(expected.get(i));
        }
        assertThat(Files.readAllBytes(cluster)).as("the cluster's recording, byte for byte")
                .isEqualTo(Files.readAllBytes(single));
    }

    private ClusterNode.Builder node(List<String> seeds) {
        return ClusterNode.builder().port(0).clusterPort(0).seedNodes(seeds).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(SECONDS).waitFor(10).lockstepDeadline(Duration.ofSeconds(20)).parcelSize(25);
    }
}
