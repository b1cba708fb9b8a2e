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
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
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
    /**
     * The world: {@code -Dorchard.cluster.world=benchmark} for the benchmark world (1,000 × 1,000
     * units, 10,000 objects, 2,000 fruit) of the seed, written as a scenario file, else the paper's.
     */
    private static final boolean BENCHMARK_WORLD = "benchmark".equals(System.getProperty("orchard.cluster.world"));
    /**
     * The agents: {@code -Dorchard.cluster.agentKind=gatherer} for light agents that keep no maps
     * ({@link Gatherer}), as many as a benchmark world takes; else the paper's five, in turn.
     */
    private static final boolean GATHERERS = "gatherer".equals(System.getProperty("orchard.cluster.agentKind"));
    /**
     * How long a lockstep tick waits for a turn, in seconds: {@code -Dorchard.cluster.turnDeadline},
     * 20 unless set. A thousand agents' threads on two cores may need longer at the first tick.
     */
    private static final int TURN_DEADLINE = Integer.getInteger("orchard.cluster.turnDeadline", 20);
    /** Each node process's heap: {@code -Dorchard.cluster.nodeHeap}, 512m unless set. */
    private static final String NODE_HEAP = System.getProperty("orchard.cluster.nodeHeap", "512m");
    private static final Pattern LAST_TICK = Pattern.compile("\\{\"tick\":(\\d+),");
    private static final Pattern COUNTS = Pattern.compile("handOvers=(\\d+), sightingsAcrossBorders=(\\d+)");

    @TempDir
    Path dir;

    /** Each node's CPU time when the agents started to connect, in nanoseconds. */
    private final List<Long> cpuBefore = new ArrayList<>();
    /** The options that load the world's scenario, if one was written. */
    private final List<String> world = new ArrayList<>();

    private static List<AgentController> agents() {
        List<AgentController> agents = new ArrayList<>();
        if (GATHERERS) {
            for (int i = 1; i <= AGENTS; i++) {
                agents.add(new Gatherer("Gatherer" + i));
            }
            return agents;
        }
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

    private static long cpu(Process node) {
        return node.info().totalCpuDuration().map(Duration::toNanos).orElse(0L);
    }

    /**
     * Prints what the run measured: each node's CPU (in all, and from the agents' first connection to
     * the game's end, per agent-tick of the game's {@code ticks}) and last health line, and the tick's
     * figures.
     */
    private void measure(List<NodeProcesses.Node> nodes, String over, long ticks) {
        List<String> said = new ArrayList<>();
        long inGame = 0;
        for (int i = 0; i < nodes.size(); i++) {
            Process node = nodes.get(i).process();
            long used = cpu(node) - cpuBefore.get(i);
            inGame += used;
            String cpu = String.format(java.util.Locale.ROOT, "%d ms of CPU, %.0f ms in the game", cpu(node) / 1_000_000,
                    used / 1e6);
            String health = "";
            for (String line : nodes.get(i).said()) {
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

    /** The last lines of a recording, read without holding all of it: a big game's is gigabytes. */
    private static List<String> lastLines(Path file) throws java.io.IOException {
        java.util.ArrayDeque<String> last = new java.util.ArrayDeque<>();
        try (Stream<String> lines = Files.lines(file, StandardCharsets.UTF_8)) {
            lines.forEach(line -> {
                if (last.size() == 3) {
                    last.removeFirst();
                }
                last.addLast(line);
            });
        }
        return new ArrayList<>(last);
    }

    /** The first line, numbered, where two recordings differ, or empty. */
    static String firstDifferentLine(Path expected, Path actual) throws java.io.IOException {
        try (BufferedReader one = Files.newBufferedReader(expected); BufferedReader other = Files.newBufferedReader(actual)) {
            for (int number = 1; ; number++) {
                String a = one.readLine();
                String b = other.readLine();
                if (a == null && b == null) {
                    return "";
                }
                if (a == null || !a.equals(b)) {
                    return "line " + number + ": the server's " + a + "\nthe cluster's " + b;
                }
            }
        }
    }

    @Test
    void threeNodeProcessesServeTheGameOneServerServesByteForByte() throws Exception {
        Path single = dir.resolve("server.ndjson");
        WorldServer.Builder serving = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(SECONDS).waitFor(AGENTS).lockstepDeadline(Duration.ofSeconds(TURN_DEADLINE)).record(single);
        if (FRUIT > 0 || BENCHMARK_WORLD) {
            Path scenario = dir.resolve("world.json");
            WorldOptions options = BENCHMARK_WORLD ? WorldOptions.BENCHMARK : WorldOptions.DEFAULT;
            ScenarioFile.write(new WorldGenerator(new SplittableRandom(SEED),
                    FRUIT > 0 ? options.withFruit(FRUIT) : options).scenario(), scenario);
            serving.scenario(scenario);
            world.addAll(List.of("--scenario", scenario.toString()));
        }
        try (WorldServer server = serving.start()) {
            play(agents(), List.of(server.port())); // not held on to: a thousand agents take gigabytes
            server.gameOver().get(1, TimeUnit.MINUTES);
        }

        Path cluster = dir.resolve("cluster.ndjson");
        List<String> common = new ArrayList<>(List.of("--seed", String.valueOf(SEED), "--clock", "lockstep",
                "--time-limit", String.valueOf(SECONDS), "--wait-for", String.valueOf(AGENTS), "--turn-deadline",
                String.valueOf(TURN_DEADLINE), "--parcel-size", PARCEL));
        common.addAll(world);
        Matcher counts;
        List<String> recorded;
        try (NodeProcesses nodes = new NodeProcesses(common, NODE_HEAP)) {
            NodeProcesses.Node first = nodes.start(List.of("--record", cluster.toString()));
            List<Integer> ports = new ArrayList<>(List.of(first.port()));
            for (int i = 1; i < NODES; i++) {
                ports.add(nodes.start(List.of("--seed-nodes", "127.0.0.1:" + first.clusterPort())).port());
            }
            List<AgentController> onCluster = agents();
            Collections.reverse(onCluster);
            nodes.nodes().forEach(node -> cpuBefore.add(cpu(node.process())));
            try {
                play(onCluster, ports);
            } catch (AssertionError e) {
                throw new AssertionError(e.getMessage() + nodes.said(), e);
            }
            String over = first.await(COUNTS, 60);
            counts = COUNTS.matcher(over);
            assertThat(counts.find()).isTrue();
            Thread.sleep(6_000); // one more health line from every node, with what it sent
            recorded = lastLines(cluster);
            Matcher last = LAST_TICK.matcher(recorded.get(recorded.size() - 1));
            measure(nodes.nodes(), over, last.find() ? Long.parseLong(last.group(1)) : 0);
        }

        try (Stream<String> lines = Files.lines(single, StandardCharsets.UTF_8)) {
            assertThat(lines.filter(line -> line.contains("\"dir\":\"missed\"")).findFirst())
                    .as("a missed turn in the server's recording").isEmpty();
        }
        assertThat(recorded.get(recorded.size() - 1)).contains("\"type\":\"GameOver\"");
        long mismatch = Files.mismatch(single, cluster);
        if (mismatch != -1) {
            assertThat(firstDifferentLine(single, cluster)).as("the first line where the recordings differ")
                    .isEmpty();
        }
        assertThat(mismatch).as("where the cluster's recording first differs from the server's, byte for byte")
                .isEqualTo(-1L);
        assertThat(Long.parseLong(counts.group(1))).as("agents walked from parcel to parcel").isPositive();
        assertThat(Long.parseLong(counts.group(2))).as("agents saw agents in other parcels").isPositive();
    }
}
