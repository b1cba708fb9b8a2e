package io.orchard.server.bench;

import ch.qos.logback.classic.Level;
import io.orchard.server.WorldServer;
import io.orchard.server.net.NetLimits;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.TickStats;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server of the load test: the benchmark world (1,000 × 1,000 units, seed 2026 by default)
 * played in real time until the test ends. {@link #start} makes it for the load generator's own
 * JVM; {@link #main} runs it as a process of its own, which {@link ServerProcess} drives through its
 * standard streams: it prints {@code @port N}, then {@code @tick N NANOS} when each tick starts
 * ({@code System.nanoTime}, which every JVM of a machine reads from the same clock), and answers
 * {@code window} with nothing and {@code figures} with {@code @figures ...} ({@link ServerFigures});
 * it stops when its standard input ends.
 */
final class LoadServer {

    private LoadServer() {}

    /** A server on {@code port} (0: any) that starts the game when {@code agents} have registered. */
    static WorldServer start(int port, long seed, int tickRate, int agents, int connections, GameListener listener)
            throws IOException {
        Scenario scenario = WorldGenerator.benchmark(seed).scenario();
        Path world = Files.createTempFile("orchard-load", ".json");
        try {
            ScenarioFile.write(scenario, world);
            return WorldServer.builder().port(port).seed(seed).scenario(world).tickRate(tickRate).timeLimit(1e6)
                    .waitFor(agents).limits(NetLimits.DEFAULT.withMaxConnections(connections)).listener(listener)
                    .start();
        } finally {
            Files.deleteIfExists(world);
        }
    }

    /** Quiet logs: a line for each of thousands of connections costs more than the connection. */
    static void quietLogs() {
        Logger root = LoggerFactory.getLogger(Logger.ROOT_LOGGER_NAME);
        if (root instanceof ch.qos.logback.classic.Logger logback) {
            logback.setLevel(Level.WARN);
        }
    }

    /** Arguments: seed, tick rate, agents to wait for, connections to allow. */
    public static void main(String[] args) throws Exception {
        quietLogs();
        PrintStream out = new PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out), false,
                StandardCharsets.UTF_8);
        long seed = Long.parseLong(args[0]);
        int tickRate = Integer.parseInt(args[1]);
        int agents = Integer.parseInt(args[2]);
        int connections = Integer.parseInt(args[3]);
        try (WorldServer server = start(0, seed, tickRate, agents, connections, new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                long now = System.nanoTime();
                synchronized (out) {
                    out.println("@tick " + (tick + 1) + " " + now);
                    out.flush();
                }
            }
        })) {
            say(out, "@port " + server.port());
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            ThreadCpu start = ThreadCpu.now();
            String command;
            while ((command = in.readLine()) != null) {
                if (command.equals("window")) {
                    server.resetTickStats();
                    start = ThreadCpu.now();
                } else if (command.equals("figures")) {
                    TickStats ticks = server.tickStats();
                    ThreadCpu.Used used = ThreadCpu.now().since(start);
                    say(out, "@figures " + new ServerFigures(ticks.ticks(), ticks.p50().toNanos() / 1e6,
                            ticks.p99().toNanos() / 1e6, ticks.max().toNanos() / 1e6, ticks.lateTicks(), used.tick(),
                            used.io(), used.process()).line());
                }
            }
        }
    }

    private static void say(PrintStream out, String line) {
        synchronized (out) {
            out.println(line);
            out.flush();
        }
    }
}
