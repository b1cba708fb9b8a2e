package io.orchard.server.bench;

import java.lang.management.ManagementFactory;
import java.util.Arrays;

/**
 * {@link TickBenchmark}'s tick timed on the thread's CPU clock instead of the wall clock, with the
 * bytes it allocates: on a machine busy with other work, JMH's wall-clock figure counts the time the
 * thread waited for a core, this does not (it still counts the caches other work spoils). Prints
 * the median and the spread of rounds of ticks.
 *
 * <pre>
 * java -cp ... io.orchard.server.bench.TickCpuTime [agents 1000] [warm-up ticks 600] [rounds 10] [ticks a round 100]
 * </pre>
 */
public final class TickCpuTime {

    private TickCpuTime() {}

    /** Runs the rounds and prints one line each, then the median. */
    public static void main(String[] args) {
        int agents = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        int warmUp = args.length > 1 ? Integer.parseInt(args[1]) : 600;
        int rounds = args.length > 2 ? Integer.parseInt(args[2]) : 10;
        int ticks = args.length > 3 ? Integer.parseInt(args[3]) : 100;
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        TickBenchmark bench = new TickBenchmark();
        bench.agents = agents;
        bench.setUp();
        for (int i = 0; i < warmUp; i++) {
            bench.tick();
        }
        double[] cpu = new double[rounds];
        double[] allocated = new double[rounds];
        long self = Thread.currentThread().getId();
        for (int r = 0; r < rounds; r++) {
            long cpuBefore = threads.getCurrentThreadCpuTime();
            long bytesBefore = threads.getThreadAllocatedBytes(self);
            long messagesBefore = bench.tick();
            long messages = messagesBefore;
            for (int i = 1; i < ticks; i++) {
                messages = bench.tick();
            }
            cpu[r] = (threads.getCurrentThreadCpuTime() - cpuBefore) / 1e6 / ticks;
            allocated[r] = (threads.getThreadAllocatedBytes(self) - bytesBefore) / 1e6 / ticks;
            System.out.printf("round %d: %.2f ms of CPU a tick, %.2f MB allocated a tick, %d messages a tick%n", r + 1,
                    cpu[r], allocated[r], (messages - messagesBefore) / (ticks - 1));
        }
        double[] sorted = cpu.clone();
        Arrays.sort(sorted);
        System.out.printf("%d agents: median %.2f ms of CPU a tick (min %.2f, max %.2f), %.2f MB allocated a tick;"
                        + " load average %.2f%n", agents, sorted[rounds / 2], sorted[0], sorted[rounds - 1],
                allocated[rounds - 1], ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
    }
}
