package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code orchard node} processes for tests, each a JVM of its own on loopback: started with the
 * options given, their output kept line by line, stopped (or killed) at the end.
 */
final class NodeProcesses implements AutoCloseable {

    private static final Pattern LISTENING =
            Pattern.compile("node listening for agents and viewers on [^:]+:(\\d+), cluster member at port (\\d+)");
    private static final Pattern TICK = Pattern.compile("^node \\S+ .* tick (\\d+) ");

    /** One node: its process, its gateway's and cluster member's ports, and all it said so far. */
    record Node(Process process, int port, int clusterPort, List<String> said, BlockingQueue<String> unread) {

        /** The first line from now on matching {@code pattern} within {@code seconds}, or a failure showing what came. */
        String await(Pattern pattern, int seconds) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            while (System.nanoTime() < deadline) {
                String line = unread.poll(100, TimeUnit.MILLISECONDS);
                if (line != null && pattern.matcher(line).find()) {
                    return line;
                }
            }
            throw new AssertionError("no line like " + pattern + " within " + seconds + " s; the node said:\n"
                    + String.join("\n", said));
        }

        /** Waits until the node says, in its health line, that the game is at {@code tick} or later. */
        void awaitTick(long tick, int seconds) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            while (System.nanoTime() < deadline) {
                String line = unread.poll(100, TimeUnit.MILLISECONDS);
                Matcher at = line == null ? null : TICK.matcher(line);
                if (at != null && at.find() && Long.parseLong(at.group(1)) >= tick) {
                    return;
                }
            }
            throw new AssertionError("the game did not reach tick " + tick + " within " + seconds + " s; the node "
                    + "said:\n" + String.join("\n", said));
        }
    }

    private final List<String> common;
    private final String heap;
    private final List<Node> nodes = new ArrayList<>();

    /** Nodes started with these options besides their ports and seed nodes, each with a heap of 512 MB. */
    NodeProcesses(List<String> common) {
        this(common, "512m");
    }

    /** Nodes started with these options besides their ports and seed nodes, each with this heap ({@code -Xmx}). */
    NodeProcesses(List<String> common, String heap) {
        this.common = List.copyOf(common);
        this.heap = heap;
    }

    /** Starts a node with {@code options} besides the common ones; returns it once it listens. */
    Node start(List<String> options) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-Xmx" + heap, "-cp", System.getProperty("java.class.path"), NodeMain.class.getName(),
                "--port", "0", "--cluster-port", "0"));
        command.addAll(common);
        command.addAll(options);
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        // A test's JVM that ends abruptly (out of memory, say) leaves no node running behind it.
        Runtime.getRuntime().addShutdownHook(new Thread(process::destroyForcibly));
        List<String> said = new CopyOnWriteArrayList<>();
        BlockingQueue<String> unread = new LinkedBlockingQueue<>();
        Thread reader = new Thread(() -> {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line = in.readLine(); line != null; line = in.readLine()) {
                    said.add(line);
                    unread.add(line);
                }
            } catch (java.io.IOException e) {
                said.add("(output ended: " + e + ")");
            }
        });
        reader.setDaemon(true);
        reader.start();
        Node started = new Node(process, 0, 0, said, unread);
        nodes.add(started);
        Matcher matcher = LISTENING.matcher(started.await(LISTENING, 120));
        assertThat(matcher.find()).isTrue();
        Node node = new Node(process, Integer.parseInt(matcher.group(1)), Integer.parseInt(matcher.group(2)), said,
                unread);
        nodes.set(nodes.size() - 1, node);
        return node;
    }

    /**
     * The options of a lockstep game of {@code seed} for {@code agents} and {@code seconds}, in parcels
     * of 25 units, a turn waited for 20 s and a silent node taken for lost after 5 s, then {@code more}.
     */
    static List<String> lockstep(long seed, double seconds, int agents, String... more) {
        List<String> options = new ArrayList<>(List.of("--seed", String.valueOf(seed), "--clock", "lockstep",
                "--time-limit", String.valueOf(seconds), "--wait-for", String.valueOf(agents), "--turn-deadline", "20",
                "--parcel-size", "25", "--down-after", "5"));
        options.addAll(List.of(more));
        return options;
    }

    /** Starts a node that joins the cluster of the first node started. */
    Node join() throws Exception {
        return start(List.of("--seed-nodes", "127.0.0.1:" + nodes.get(0).clusterPort()));
    }

    /** Every node started, in order. */
    List<Node> nodes() {
        return nodes;
    }

    /** What every node said, for a failure's message. */
    String said() {
        StringBuilder all = new StringBuilder();
        for (Node node : nodes) {
            all.append("\n--- a node said:\n");
            node.said().forEach(line -> all.append(line).append('\n'));
        }
        return all.toString();
    }

    /** Asks every node still running to leave (SIGTERM), and kills those that do not within a minute. */
    @Override
    public void close() throws InterruptedException {
        for (Node node : nodes) {
            node.process().destroy();
        }
        for (Node node : nodes) {
            if (!node.process().waitFor(60, TimeUnit.SECONDS)) {
                node.process().destroyForcibly();
            }
        }
    }
}
