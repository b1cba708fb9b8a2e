package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.WorldOptions;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The equivalence of a cluster with one server, in three JVMs: fifteen of the paper's agents play a
 * lockstep game on one world server, then the same game on three {@code orchard node} processes on
 * loopback, each agent connected to one of the three nodes' ports, the world in parcels of 25 units:
 * the two recordings are the same file, byte for byte, and the nodes say that agents walked from
 * parcel to parcel and saw agents in other parcels.
 */
class NodeProcessesTest {

    private static final long SEED = 8;
    /** Simulated seconds: {@code -Dorchard.cluster.seconds}, 30 unless set. */
    private static final double SECONDS = Double.parseDouble(System.getProperty("orchard.cluster.seconds", "30"));
    /** Agents, a multiple of five: {@code -Dorchard.cluster.agents}, 15 unless set. */
    private static final int AGENTS = Integer.getInteger("orchard.cluster.agents", 15);
    /** Nodes: {@code -Dorchard.cluster.nodes}, 3 unless set. */
    private static final int NODES = Integer.getInteger("orchard.cluster.nodes", 3);
    /** The side of the parcels: {@code -Dorchard.cluster.parcel}, 25 unless set. */
    private static final String PARCEL = System.getProperty("orchard.cluster.parcel", "25");
    /**
     * Fruit in the world: {@code -Dorchard.cluster.fruit}; unless set, the paper's world of the seed
     * (30 fruit), else that world with this many fruit, as a scenario file that the server and every
     * node load, so that many agents play long enough to be measured.
     */
    private static final int FRUIT = Integer.getInteger("orchard.cluster.fruit", 0);
    /** Each node process's heap: {@code -Dorchard.cluster.nodeHeap}, 512m unless set. */
    private static final String NODE_HEAP = System.getProperty("orchard.cluster.nodeHeap", "512m");
    private static final Pattern LAST_TICK = Pattern.compile("\\{\"tick\":(\\d+),");
    private static final Pattern LISTENING =
            Pattern.compile("node listening for agents and viewers on [^:]+:(\\d+), cluster member at port (\\d+)");
    private static final Pattern COUNTS = Pattern.compile("handOvers=(\\d+), sightingsAcrossBorders=(\\d+)");

    @TempDir
    Path dir;

    private final List<Process> nodes = new ArrayList<>();
    private final List<BlockingQueue<String>> outputs = new ArrayList<>();
    /** Each node's CPU time when the agents started to connect, in nanoseconds. */
    private final List<Long> cpuBefore = new ArrayList<>();
    /** The options that load the world's scenario, if one was written. */
    private final List<String> world = new ArrayList<>();

    @AfterEach
    void stopTheNodes() throws InterruptedException {
        for (Process node : nodes) {
            node.destroy();
        }
        for (Process node : nodes) {
            if (!node.waitFor(60, TimeUnit.SECONDS)) {
                node.destroyForcibly();
            }
        }
    }

    private static List<AgentController> agents() {
        List<AgentController> agents = new ArrayList<>();
        for (int i = 1; i <= AGENTS / Species.values().length; i++) {
            for (Species species : Species.values()) {
                agents.add(species.create(species.agentName() + i));
            }
        }
        return agents;
    }

    private static void play(List<AgentController> agents, List<Integer> ports) throws Exception {
        ExecutorService threads = Executors.newFixedThreadPool(agents.size());
        try {
            List<Future<GameOverMessage>> ends = new ArrayList<>();
            for (int i = 0; i < agents.size(); i++) {
                AgentController agent = agents.get(i);
                int port = ports.get(i % ports.size());
                ends.add(threads.submit(() -> agent.run("127.0.0.1", port)));
            }
            for (Future<GameOverMessage> end : ends) {
                try {
                    assertThat(end.get(10, TimeUnit.MINUTES)).as("the agent's game ended").isNotNull();
                } catch (java.util.concurrent.TimeoutException e) {
                    throw new AssertionError("an agent's game did not end within 10 minutes", e);
                }
            }
        } finally {
            threads.shutdownNow();
        }
    }

    /** Starts an {@code orchard node} in a JVM of its own; returns its gateway's and its cluster member's ports. */
    private int[] node(List<String> options) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + NODE_HEAP, "-cp", System.getProperty("java.class.path"), NodeMain.class.getName(), "--port", "0",
                "--cluster-port", "0", "--seed", String.valueOf(SEED), "--clock", "lockstep", "--time-limit",
                String.valueOf(SECONDS), "--wait-for", String.valueOf(AGENTS), "--turn-deadline", "20",
                "--parcel-size", PARCEL));
        command.addAll(world);
        command.addAll(options);
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        nodes.add(process);
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        outputs.add(lines);
        Thread reader = new Thread(() -> {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line = in.readLine(); line != null; line = in.readLine()) {
                    lines.add(line);
                }
            } catch (java.io.IOException e) {
                lines.add("(output ended: " + e + ")");
            }
        });
        reader.setDaemon(true);
        reader.start();
        String line = await(lines, LISTENING, 120);
        Matcher matcher = LISTENING.matcher(line);
        assertThat(matcher.find()).isTrue();
        return new int[] {Integer.parseInt(matcher.group(1)), Integer.parseInt(matcher.group(2))};
    }

    /** The first line matching {@code pattern} within {@code seconds}, or a failure that shows what came. */
    private static String await(BlockingQueue<String> lines, Pattern pattern, int seconds) throws InterruptedException {
        List<String> seen = new ArrayList<>();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (System.nanoTime() < deadline) {
            String line = lines.poll(100, TimeUnit.MILLISECONDS);
            if (line != null) {
                seen.add(line);
                if (pattern.matcher(line).find()) {
                    return line;
                }
            }
        }
        throw new AssertionError("no line like " + pattern + " within " + seconds + " s; the node said:\n"
                + String.join("\n", seen));
    }

    private static long cpu(Process node) {
        return node.info().totalCpuDuration().map(Duration::toNanos).orElse(0L);
    }

    /**
     * Prints what the run measured: each node's CPU (in all, and from the agents' first connection to
     * the game's end, per agent-tick of the game's {@code ticks}) and last health line, and the tick's
     * figures.
     */
    private void measure(String over, long ticks) {
        List<String> said = new ArrayList<>();
        long inGame = 0;
        for (int i = 0; i < nodes.size(); i++) {
            long used = cpu(nodes.get(i)) - cpuBefore.get(i);
            inGame += used;
            String cpu = nodes.get(i).info().totalCpuDuration().map(d -> d.toMillis() + " ms of CPU").orElse("?")
                    + String.format(java.util.Locale.ROOT, ", %.0f ms in the game", used / 1e6);
            String health = "";
            for (String line : outputs.get(i)) {
                if (line.startsWith("node ")) {
                    health = line;
                }
            }
            said.add(cpu + "; " + health);
        }
        System.out.printf(java.util.Locale.ROOT, "%d agents, %d nodes, parcels of %s, %.0f s, %d ticks; CPU of all "
                        + "nodes in the game %.1f µs per agent-tick%n%s%n%s%n", AGENTS, NODES, PARCEL, SECONDS, ticks,
                inGame / 1e3 / Math.max(1, ticks * AGENTS), over, String.join("\n", said));
    }

    @Test
    void threeNodeProcessesServeTheGameOneServerServesByteForByte() throws Exception {
        Path single = dir.resolve("server.ndjson");
        List<AgentController> onServer = agents();
        WorldServer.Builder serving = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(SECONDS).waitFor(AGENTS).lockstepDeadline(Duration.ofSeconds(20)).record(single);
        if (FRUIT > 0) {
            Path scenario = dir.resolve("world.json");
            ScenarioFile.write(new WorldGenerator(new SplittableRandom(SEED), WorldOptions.DEFAULT.withFruit(FRUIT))
                    .scenario(), scenario);
            serving.scenario(scenario);
            world.addAll(List.of("--scenario", scenario.toString()));
        }
        try (WorldServer server = serving.start()) {
            play(onServer, List.of(server.port()));
            server.gameOver().get(1, TimeUnit.MINUTES);
        }

        Path cluster = dir.resolve("cluster.ndjson");
        int[] first = node(List.of("--record", cluster.toString()));
        List<Integer> ports = new ArrayList<>(List.of(first[0]));
        for (int i = 1; i < NODES; i++) {
            ports.add(node(List.of("--seed-nodes", "127.0.0.1:" + first[1]))[0]);
        }
        List<AgentController> onCluster = agents();
        Collections.reverse(onCluster);
        nodes.forEach(node -> cpuBefore.add(cpu(node)));
        try {
            play(onCluster, ports);
        } catch (AssertionError e) {
            StringBuilder said = new StringBuilder();
            for (BlockingQueue<String> output : outputs) {
                said.append("\n--- a node said:\n");
                output.forEach(line -> said.append(line).append('\n'));
            }
            throw new AssertionError(e.getMessage() + said, e);
        }
        String over = await(outputs.get(0), COUNTS, 60);
        Matcher counts = COUNTS.matcher(over);
        assertThat(counts.find()).isTrue();
        Thread.sleep(6_000); // one more health line from every node, with what it sent
        List<String> recorded = Files.readAllLines(cluster);
        Matcher last = LAST_TICK.matcher(recorded.get(recorded.size() - 1));
        measure(over, last.find() ? Long.parseLong(last.group(1)) : 0);

        assertThat(Files.readString(single, StandardCharsets.UTF_8)).as("no turn was missed")
                .doesNotContain("\"dir\":\"missed\"").contains("\"type\":\"GameOver\"");
        List<String> expected = Files.readAllLines(single);
        List<String> actual = Files.readAllLines(cluster);
        for (int i = 0; i < Math.min(expected.size(), actual.size()); i++) {
            assertThat(actual.get(i)).as("line %d of the cluster's recording", i + 1).isEqualTo(expected.get(i));
        }
        assertThat(Files.readAllBytes(cluster)).as("the cluster's recording, byte for byte")
                .isEqualTo(Files.readAllBytes(single));
        assertThat(Long.parseLong(counts.group(1))).as("agents walked from parcel to parcel").isPositive();
        assertThat(Long.parseLong(counts.group(2))).as("agents saw agents in other parcels").isPositive();
    }
}
