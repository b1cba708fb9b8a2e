package io.orchard.server.bench;

import io.netty.bootstrap.Bootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelHandler;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioSocketChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.netty.util.concurrent.DefaultThreadFactory;
import io.orchard.server.sim.GameListener;
import io.orchard.server.world.WorldGenerator;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * Puts a world server under the load of many agents: it starts the server at 20 ticks a second on
 * the benchmark world (1,000 × 1,000 units, 10,000 objects), connects N agent clients and 5
 * viewers over loopback, and lets every agent ask for its perception and move whenever one
 * arrives. After a warm-up it measures for a while and prints the server's tick work
 * (p50/p99/max), how many of the perceptions asked for came in the next tick, how late they came,
 * the messages per second each way, the CPU used by the server (per perception delivered), the
 * clients and the rest, and the heap.
 *
 * <pre>
 * ./mvnw -B -q -pl server -am -Pload verify -DskipTests -Dload.args="--agents 1000"
 * </pre>
 *
 * Options: {@code --agents N} (1000), {@code --viewers N} (5), {@code --warmup S} (15),
 * {@code --seconds S} (30), {@code --tick-rate N} (20), {@code --client-threads N} (2),
 * {@code --seed N} (2026), {@code --form lean|ordinary} (lean: the clients read the lean form),
 * {@code --server inline|process} (inline: the server runs in this JVM; process: in a JVM of its
 * own, with the options of {@code --server-jvm}, "-Xms1g -Xmx1g -XX:+UseG1GC"),
 * {@code --server-cpus LIST} and {@code --client-cpus LIST} (cores as {@code taskset -c} takes them:
 * the server process is started on the first, this JVM moved to the second).
 */
public final class LoadGenerator {

    private LoadGenerator() {}

    public static void main(String[] args) throws Exception {
        Map<String, String> options = parse(args);
        int agents = Integer.parseInt(options.getOrDefault("agents", "1000"));
        int viewers = Integer.parseInt(options.getOrDefault("viewers", "5"));
        int warmup = Integer.parseInt(options.getOrDefault("warmup", "15"));
        int seconds = Integer.parseInt(options.getOrDefault("seconds", "30"));
        int tickRate = Integer.parseInt(options.getOrDefault("tick-rate", "20"));
        int clientThreads = Integer.parseInt(options.getOrDefault("client-threads", "2"));
        long seed = Long.parseLong(options.getOrDefault("seed", "2026"));
        boolean lean = choice(options, "form", "lean", "ordinary");
        String serverCpus = options.getOrDefault("server-cpus", "");
        String clientCpus = options.getOrDefault("client-cpus", "");
        boolean ownProcess = !choice(options, "server", "inline", "process") || !serverCpus.isEmpty();
        List<String> serverJvm = Arrays.asList(options.getOrDefault("server-jvm", "-Xms1g -Xmx1g -XX:+UseG1GC")
                .trim().split("\\s+"));

        LoadServer.quietLogs();
        if (!clientCpus.isEmpty()) {
            pin(clientCpus);
        }
        LoadClients.Stats stats = new LoadClients.Stats();
        int connections = agents + viewers + 16;
        ServerUnderLoad server = ownProcess
                ? new ServerProcess(serverJvm, serverCpus, seed, tickRate, agents, connections, stats::tickStarted)
                : new InlineServer(LoadServer.start(0, seed, tickRate, agents, connections, new GameListener() {
                    @Override
                    public void tickEnded(long tick, double time) {
                        stats.tickStarted(tick + 1, System.nanoTime());
                    }
                }));
        EventLoopGroup group = new MultiThreadIoEventLoopGroup(clientThreads,
                new DefaultThreadFactory("loadgen-io", true), NioIoHandler.newFactory());
        List<Channel> channels = new ArrayList<>();
        try {
            double half = WorldGenerator.benchmark(seed).scenario().bounds().width() / 2;
            for (int i = 0; i < viewers; i++) {
                channels.add(connect(group, server.port(), () -> new LoadClients.Viewer(stats)));
            }
            long setup = System.nanoTime();
            for (int i = 0; i < agents; i++) {
                // No more than half the connections the server lets wait for their Hello at once.
                while (i - stats.welcomed.sum() > 128) {
                    if (System.nanoTime() - setup > 180e9) {
                        throw new IllegalStateException("only " + stats.welcomed.sum() + " of " + i
                                + " agents welcomed in 3 minutes");
                    }
                    Thread.sleep(1);
                }
                String name = "L" + i;
                long agentSeed = seed * 31 + i;
                channels.add(connect(group, server.port(),
                        () -> new LoadClients.Agent(name, stats, half, agentSeed, lean)));
            }
            while (stats.registered.sum() < agents || stats.ticksStarted.sum() == 0) {
                if (System.nanoTime() - setup > 180e9) {
                    throw new IllegalStateException("only " + stats.registered.sum() + " of " + agents
                            + " agents registered in 3 minutes");
                }
                Thread.sleep(100);
            }
            System.out.printf(Locale.ROOT, "%d agents (%s form) and %d viewers connected and registered in %.1f s,"
                            + " server %s; warming up %d s%n", agents, lean ? "lean" : "ordinary", viewers,
                    (System.nanoTime() - setup) / 1e9, ownProcess ? "in its own process" + (serverCpus.isEmpty() ? ""
                            : " on cores " + serverCpus + ", clients on " + (clientCpus.isEmpty() ? "any" : clientCpus))
                            : "in this JVM", warmup);
            Thread.sleep(warmup * 1000L);
            LoadWindow window = LoadWindow.start(stats, server);
            long end = System.nanoTime() + seconds * 1_000_000_000L;
            while (System.nanoTime() < end) {
                Thread.sleep(250);
                window.sampleHeap();
            }
            window.finish(server, stats).print(agents, viewers, tickRate, seconds, lean, ownProcess);
        } finally {
            for (Channel channel : channels) {
                channel.close();
            }
            group.shutdownGracefully(0, 1, TimeUnit.SECONDS).syncUninterruptibly();
            server.close();
        }
    }

    /** Moves every thread of this JVM, and those it starts later, to these cores. */
    private static void pin(String cpus) throws IOException, InterruptedException {
        Process taskset = new ProcessBuilder("taskset", "-a", "-p", "-c", cpus,
                Long.toString(ProcessHandle.current().pid())).redirectErrorStream(true).start();
        String said = new String(taskset.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        if (taskset.waitFor() != 0) {
            throw new IllegalStateException("taskset could not pin the load generator to cores " + cpus + ": " + said);
        }
    }

    private static boolean choice(Map<String, String> options, String name, String yes, String no) {
        String value = options.getOrDefault(name, yes);
        if (!value.equals(yes) && !value.equals(no)) {
            throw new IllegalArgumentException("--" + name + " is " + yes + " or " + no + ", was '" + value + "'");
        }
        return value.equals(yes);
    }

    private static Channel connect(EventLoopGroup group, int port, Supplier<ChannelHandler> client)
            throws InterruptedException {
        return new Bootstrap().group(group).channel(NioSocketChannel.class)
                .option(ChannelOption.TCP_NODELAY, true)
                .handler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel channel) {
                        channel.pipeline().addLast("frame", new LineBasedFrameDecoder(16 << 20))
                                .addLast("client", client.get());
                    }
                })
                .connect(new InetSocketAddress("127.0.0.1", port)).sync().channel();
    }

    private static Map<String, String> parse(String[] args) {
        Map<String, String> options = new HashMap<>();
        for (int i = 0; i < args.length; i++) {
            String arg = args[i];
            if (!arg.startsWith("--")) {
                throw new IllegalArgumentException("options are --name value, was '" + arg + "'");
            }
            String name = arg.substring(2);
            String value;
            int eq = name.indexOf('=');
            if (eq >= 0) {
                value = name.substring(eq + 1);
                name = name.substring(0, eq);
            } else if (i + 1 < args.length) {
                value = args[++i];
            } else {
                throw new IllegalArgumentException("option --" + name + " needs a value");
            }
            options.put(name, value);
        }
        return options;
    }
}
