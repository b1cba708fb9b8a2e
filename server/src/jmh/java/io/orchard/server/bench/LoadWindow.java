package io.orchard.server.bench;

import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.Locale;

/** The measured window of a load test: what the clients counted, the server's figures, CPU and heap. */
final class LoadWindow {

    private final long startNanos;
    private final ThreadCpu cpu;
    private final long[] machine;
    private final long gcCount;
    private final long gcMillis;
    private long peakHeap;

    private LoadWindow(long startNanos, ThreadCpu cpu, long[] machine, long gcCount, long gcMillis) {
        this.startNanos = startNanos;
        this.cpu = cpu;
        this.machine = machine;
        this.gcCount = gcCount;
        this.gcMillis = gcMillis;
    }

    static LoadWindow start(LoadClients.Stats stats, ServerUnderLoad server) {
        stats.reset();
        stats.measuring = true;
        server.startWindow();
        return new LoadWindow(System.nanoTime(), ThreadCpu.now(), machineJiffies(), gcCount(), gcMillis());
    }

    void sampleHeap() {
        peakHeap = Math.max(peakHeap, ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed());
    }

    Result finish(ServerUnderLoad server, LoadClients.Stats stats) {
        ServerFigures figures = server.endWindow();
        double window = (System.nanoTime() - startNanos) / 1e9;
        stats.measuring = false;
        ThreadCpu.Used used = ThreadCpu.now().since(cpu);
        long[] machineAfter = machineJiffies();
        double machineBusy = machineAfter[1] - machine[1] == 0 ? 0
                : (double) (machineAfter[0] - machine[0]) / (machineAfter[1] - machine[1]);
        int cores = machineCores();
        return new Result(window, figures, stats.requestToPerception.millis(0.5), stats.requestToPerception.millis(0.99),
                stats.perceptionAge.millis(0.5), stats.perceptionAge.millis(0.99),
                stats.linesSent.sum() / window, (stats.agentLinesReceived.sum() + stats.viewerLinesReceived.sum()) / window,
                stats.perceptions.sum() / window, stats.viewerBytesReceived.sum() / window, stats.agentBytesReceived.sum()
                / window, used, machineBusy * cores, peakHeap, oldGenAfterGc(),
                gcCount() - gcCount, gcMillis() - gcMillis, stats.errors.sum(), stats.closed.sum(), stats.retries.sum(),
                cores, uptimeLoad());
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

    /** The machine's cores, counted in /proc/stat: this JVM may be pinned to fewer. */
    private static int machineCores() {
        try {
            return (int) Files.readAllLines(Path.of("/proc/stat")).stream().filter(l -> l.matches("cpu\\d+ .*")).count();
        } catch (IOException | RuntimeException e) {
            return Runtime.getRuntime().availableProcessors();
        }
    }

    /** The load averages of /proc/loadavg (1, 5, 15 minutes), or "?" where there is none. */
    private static String uptimeLoad() {
        try {
            String[] load = Files.readString(Path.of("/proc/loadavg")).trim().split("\\s+");
            return load[0] + " " + load[1] + " " + load[2];
        } catch (IOException | RuntimeException e) {
            return "?";
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

    record Result(double window, ServerFigures server, double requestP50, double requestP99, double ageP50,
                  double ageP99, double inPerSecond, double outPerSecond, double perceptionsPerSecond,
                  double viewerBytesPerSecond, double agentBytesPerSecond, ThreadCpu.Used here, double machineCpu,
                  long peakHeap, long oldAfterGc, long gcs, long gcMillis, long errors, long closed, long retries,
                  int cores, String load) {

        void print(int agents, int viewers, int tickRate, int seconds, boolean lean, boolean ownProcess) {
            double ticksPerSecond = server.ticks() / window;
            double delivered = 100 * perceptionsPerSecond / (agents * ticksPerSecond);
            double serverThreads = (server.tick() + server.io()) / window;
            double serverCpu = ownProcess ? server.process() / window : serverThreads;
            double perPerception = 1e6 * serverCpu / perceptionsPerSecond;
            double vm = here.process() - here.tick() - here.io() - here.clients() - here.otherJava();
            System.out.printf(Locale.ROOT, "%n== %d agents (%s), %d viewers, %d ticks/s asked, %d s measured, %d cores, %s,"
                            + " load average %s ==%n", agents, lean ? "lean" : "ordinary", viewers, tickRate, seconds,
                    cores, LocalDate.now(), load);
            System.out.printf(Locale.ROOT, "ticks        %.2f per second; work p50 %.2f ms, p99 %.2f ms, max %.2f ms; %d late%n",
                    ticksPerSecond, server.p50(), server.p99(), server.max(), server.late());
            System.out.printf(Locale.ROOT, "perception   %.0f per second, %.1f %% of one per agent per tick; request to"
                    + " arrival p50 %.1f ms, p99 %.1f ms; age at arrival p50 %.1f ms, p99 %.1f ms%n",
                    perceptionsPerSecond, delivered, requestP50, requestP99, ageP50, ageP99);
            System.out.printf(Locale.ROOT, "messages     clients to server %.0f/s, server to clients %.0f/s (agents %.1f MB/s,"
                    + " viewers %.1f MB/s)%n", inPerSecond, outPerSecond, agentBytesPerSecond / 1e6,
                    viewerBytesPerSecond / 1e6);
            if (ownProcess) {
                System.out.printf(Locale.ROOT, "cpu (cores)  server process %.2f (tick thread %.2f, I/O %.2f, GC+JIT+VM"
                        + " %.2f); load generator %.2f (clients %.2f); whole machine %.2f of %d%n",
                        server.process() / window, server.tick() / window, server.io() / window,
                        (server.process() - server.tick() - server.io()) / window, here.process() / window,
                        here.clients() / window, machineCpu, cores);
            } else {
                System.out.printf(Locale.ROOT, "cpu (cores)  tick thread %.2f, server I/O %.2f, clients %.2f, GC+JIT+VM %.2f,"
                        + " other threads %.2f; process %.2f; whole machine %.2f of %d%n",
                        server.tick() / window, server.io() / window, here.clients() / window, vm / window,
                        here.otherJava() / window, here.process() / window, machineCpu, cores);
            }
            System.out.printf(Locale.ROOT, "per perception  %.1f µs of server CPU (%s)%n", perPerception,
                    ownProcess ? "the whole server process" : "tick thread and server I/O threads");
            System.out.printf(Locale.ROOT, "heap         peak used %d MB, old generation after GC %d MB; %d GCs, %d ms%s%n",
                    peakHeap >> 20, oldAfterGc >> 20, gcs, gcMillis, ownProcess ? " (the load generator's JVM)" : "");
            System.out.printf(Locale.ROOT, "errors       %d error lines, %d connections closed, %d perception requests "
                    + "sent again after a second without one%n", errors, closed, retries);
            System.out.printf(Locale.ROOT, "| %d | %.2f | %.1f / %.1f / %.1f | %.1f %% | %.1f / %.1f | %.0f / %.0f | %.2f / %.2f"
                            + " / %.2f | %.1f | %.2f | %s |%n",
                    agents, ticksPerSecond, server.p50(), server.p99(), server.max(), delivered, ageP50, ageP99,
                    inPerSecond, outPerSecond, server.tick() / window, server.io() / window,
                    (ownProcess ? here.process() : here.clients()) / window, perPerception, machineCpu, load);
        }
    }
}
