package io.orchard.server.bench;

import com.sun.management.OperatingSystemMXBean;
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
import io.orchard.server.WorldServer;
import io.orchard.server.net.NetLimits;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.TickStats;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;

/**
 * Puts a world server under the load of many agents: it starts the server in this JVM at 20 ticks
 * a second on the benchmark world (1,000 × 1,000 units, 10,000 objects), connects N agent clients
 * and 5 viewers over loopback, and lets every agent ask for its perception and move on every tick.
 * After a warm-up it measures for a while and prints the server's tick work (p50/p99/max), the
 * perception delay clients see (p50/p99), the messages per second each way, the CPU used by the
 * server's threads, the clients' threads and the rest of the JVM, and the heap.
 *
 * <pre>
 * ./mvnw -B -q -pl server -am -Pload verify -DskipTests -Dload.args="--agents 1000"
 * </pre>
 *
 * Options: {@code --agents N} (1000), {@code --viewers N} (5), {@code --warmup S} (15),
 * {@code --seconds S} (30), {@code --tick-rate N} (20), {@code --client-threads N} (2),
 * {@code --seed N} (2026).
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

        Scenario scenario = WorldGenerator.benchmark(seed).scenario();
        Path world = Files.createTempFile("orchard-load", ".json");
        ScenarioFile.write(scenario, world);
        LoadClients.Stats stats = new LoadClients.Stats();
        WorldServer server = WorldServer.builder().port(0).seed(seed).scenario(world).tickRate(tickRate)
                .timeLimit(1e6).waitFor(agents)
                .limits(NetLimits.DEFAULT.withMaxConnections(agents + viewers + 16))
                .listener(new GameListener() {
                    @Override
                    public void tickEnded(long tick, double time) {
                        stats.tickStarted(tick + 1, System.nanoTime());
                    }
                })
                .start();
        EventLoopGroup group = new MultiThreadIoEventLoopGroup(clientThreads,
                new DefaultThreadFactory("loadgen-io", true), NioIoHandler.newFactory());
        List<Channel> channels = new ArrayList<>();
        try {
            double half = scenario.bounds().width() / 2;
            for (int i = 0; i < viewers; i++) {
                channels.add(connect(group, server.port(), () -> new LoadClients.Viewer(stats)));
            }
            long setup = System.nanoTime();
            for (int i = 0; i < agents; i++) {
                String name = "L" + i;
                long agentSeed = seed * 31 + i;
                channels.add(connect(group, server.port(), () -> new LoadClients.Agent(name, stats, half, agentSeed)));
            }
            while (server.phase() != Phase.RUNNING) {
                if (System.nanoTime() - setup > 180e9) {
                    throw new IllegalStateException("only " + stats.registered.sum() + " of " + agents
                            + " agents registered in 3 minutes");
                }
                Thread.sleep(100);
            }
            System.out.printf(Locale.ROOT, "%d agents and %d viewers connected and registered in %.1f s; warming up %d s%n",
                    agents, viewers, (System.nanoTime() - setup) / 1e9, warmup);
            Thread.sleep(warmup * 1000L);
            Measurement measurement = Measurement.start(stats, server);
            long end = System.nanoTime() + seconds * 1_000_000_000L;
            while (System.nanoTime() < end) {
                Thread.sleep(250);
                measurement.sampleHeap();
            }
            measurement.finish(server, stats).print(agents, viewers, tickRate, seconds);
        } finally {
            for (Channel channel : channels) {
                channel.close();
            }
            group.shutdownGracefully(0, 1, java.util.concurrent.TimeUnit.SECONDS).syncUninterruptibly();
            server.close();
            Files.deleteIfExists(world);
        }
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

    /** CPU, heap and counters between the start and the end of the measured window. */
    private static final class Measurement {

        private final long startNanos;
        private final long processCpu;
        private final Map<Long, Long> threadCpu;
        private final long[] machine;
        private final long gcCount;
        private final long gcMillis;
        private long peakHeap;

        private Measurement(long startNanos, long processCpu, Map<Long, Long> threadCpu, long[] machine, long gcCount,
                            long gcMillis) {
            this.startNanos = startNanos;
            this.processCpu = processCpu;
            this.threadCpu = threadCpu;
            this.machine = machine;
            this.gcCount = gcCount;
            this.gcMillis = gcMillis;
        }

        static Measurement start(LoadClients.Stats stats, WorldServer server) {
            stats.reset();
            stats.measuring = true;
            server.resetTickStats();
            return new Measurement(System.nanoTime(), processCpu(), threadCpu(), machineJiffies(), gcCount(), gcMillis());
        }

        void sampleHeap() {
            peakHeap = Math.max(peakHeap, ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed());
        }

        Result finish(WorldServer server, LoadClients.Stats stats) {
            double window = (System.nanoTime() - startNanos) / 1e9;
            TickStats ticks = server.tickStats();
            stats.measuring = false;
            Map<Long, Long> after = threadCpu();
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            double tickThread = 0;
            double serverIo = 0;
            double clients = 0;
            double otherJava = 0;
            for (ThreadInfo info : threads.getThreadInfo(after.keySet().stream().mapToLong(Long::longValue).toArray())) {
                if (info == null) {
                    continue;
                }
                double used = (after.get(info.getThreadId()) - threadCpu.getOrDefault(info.getThreadId(), 0L)) / 1e9;
                String name = info.getThreadName();
                if (name.startsWith("orchard-tick")) {
                    tickThread += used;
                } else if (name.startsWith("orchard-")) {
                    serverIo += used;
                } else if (name.startsWith("loadgen")) {
                    clients += used;
                } else {
                    otherJava += used;
                }
            }
            double process = (processCpu() - processCpu) / 1e9;
            long[] machineAfter = machineJiffies();
            double machineBusy = machineAfter[1] - machine[1] == 0 ? 0
                    : (double) (machineAfter[0] - machine[0]) / (machineAfter[1] - machine[1]);
            int cores = Runtime.getRuntime().availableProcessors();
            return new Result(window, ticks, stats.requestToPerception.millis(0.5), stats.requestToPerception.millis(0.99),
                    stats.perceptionAge.millis(0.5), stats.perceptionAge.millis(0.99),
                    stats.linesSent.sum() / window, (stats.agentLinesReceived.sum() + stats.viewerLinesReceived.sum()) / window,
                    stats.perceptions.sum() / window, stats.viewerBytesReceived.sum() / window,
                    tickThread / window, serverIo / window, clients / window, (process - tickThread - serverIo - clients
                    - otherJava) / window, otherJava / window, process / window, machineBusy * cores,
                    peakHeap, oldGenAfterGc(), gcCount() - gcCount, gcMillis() - gcMillis, stats.errors.sum(),
                    stats.closed.sum(), stats.retries.sum(), cores);
        }

        private static long processCpu() {
            return ((OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime();
        }

        private static Map<Long, Long> threadCpu() {
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            Map<Long, Long> cpu = new HashMap<>();
            for (long id : threads.getAllThreadIds()) {
                long used = threads.getThreadCpuTime(id);
                if (used >= 0) {
                    cpu.put(id, used);
                }
            }
            return cpu;
        }

        /** Busy and total jiffies of the whole machine, from /proc/stat; zeros where there is none. */
        private static long[] machineJiffies() {
            try {
                String[] cpu = Files.readAllLines(Path.of("/proc/stat")).get(0).trim().split("\\s+");
                long total = 0;
                for (int i = 1; i < cpu.length; i++) {
                    total += Long.parseLong(cpu[i]);
                }
                long idle = Long.parseLong(cpu[4]) + (cpu.length > 5 ? Long.parseLong(cpu[5]) : 0);
                return new long[] {total - idle, total};
            } catch (IOException | RuntimeException e) {
                return new long[] {0, 0};
            }
        }

        private static long gcCount() {
            return ManagementFactory.getGarbageCollectorMXBeans().stream()
                    .mapToLong(GarbageCollectorMXBean::getCollectionCount).sum();
        }

        private static long gcMillis() {
            return ManagementFactory.getGarbageCollectorMXBeans().stream()
                    .mapToLong(GarbageCollectorMXBean::getCollectionTime).sum();
        }

        /** What the heap's old generation held after its last collection: the live set, roughly. */
        private static long oldGenAfterGc() {
            long live = 0;
            for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
                if (pool.getType() == MemoryType.HEAP && pool.getCollectionUsage() != null
                        && pool.getName().toLowerCase(Locale.ROOT).contains("old")) {
                    live += pool.getCollectionUsage().getUsed();
                }
            }
            return live;
        }
    }

    private record Result(double window, TickStats ticks, double requestP50, double requestP99, double ageP50,
                          double ageP99, double inPerSecond, double outPerSecond, double perceptionsPerSecond,
                          double viewerBytesPerSecond, double tickCpu, double ioCpu, double clientCpu, double vmCpu,
                          double otherJavaCpu, double processCpu, double machineCpu, long peakHeap, long oldAfterGc,
                          long gcs, long gcMillis, long errors, long closed, long retries, int cores) {

        void print(int agents, int viewers, int tickRate, int seconds) {
            double ticksPerSecond = ticks.ticks() / window;
            System.out.printf(Locale.ROOT, "%n== %d agents, %d viewers, %d ticks/s asked, %d s measured, %d cores, %s ==%n",
                    agents, viewers, tickRate, seconds, cores, LocalDate.now());
            System.out.printf(Locale.ROOT, "ticks        %.2f per second; work p50 %.2f ms, p99 %.2f ms, max %.2f ms; %d late%n",
                    ticksPerSecond, ms(ticks.p50().toNanos()), ms(ticks.p99().toNanos()), ms(ticks.max().toNanos()),
                    ticks.lateTicks());
            System.out.printf(Locale.ROOT, "perception   request to arrival p50 %.1f ms, p99 %.1f ms; age at arrival p50 %.1f ms,"
                    + " p99 %.1f ms; %.0f per second%n", requestP50, requestP99, ageP50, ageP99, perceptionsPerSecond);
            System.out.printf(Locale.ROOT, "messages     clients to server %.0f/s, server to clients %.0f/s (viewers %.1f MB/s)%n",
                    inPerSecond, outPerSecond, viewerBytesPerSecond / 1e6);
            System.out.printf(Locale.ROOT, "cpu (cores)  tick thread %.2f, server I/O %.2f, clients %.2f, GC+JIT+VM %.2f,"
                    + " other threads %.2f; process %.2f of %d; whole machine %.2f%n",
                    tickCpu, ioCpu, clientCpu, vmCpu, otherJavaCpu, processCpu, cores, machineCpu);
            System.out.printf(Locale.ROOT, "heap         peak used %d MB, old generation after GC %d MB; %d GCs, %d ms%n",
                    peakHeap >> 20, oldAfterGc >> 20, gcs, gcMillis);
            System.out.printf(Locale.ROOT, "errors       %d error lines, %d connections closed, %d perception requests "
                    + "sent again after a second without one%n", errors, closed, retries);
            System.out.printf(Locale.ROOT, "| %d | %.2f | %.2f | %.2f | %.2f | %.1f / %.1f | %.0f / %.0f | %.2f / %.2f / %.2f"
                            + " | %.2f | %d / %d |%n",
                    agents, ticksPerSecond, ms(ticks.p50().toNanos()), ms(ticks.p99().toNanos()), ms(ticks.max().toNanos()),
                    ageP50, ageP99, inPerSecond, outPerSecond, tickCpu, ioCpu, clientCpu, processCpu, peakHeap >> 20,
                    oldAfterGc >> 20);
        }

        private static double ms(long nanos) {
            return nanos / 1e6;
        }
    }
}
