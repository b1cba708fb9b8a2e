package io.orchard.server.bench;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.function.LongSupplier;

/**
 * Times a benchmark's operation on the thread's CPU clock instead of the wall clock, with the bytes
 * it allocates: on a machine busy with other work, JMH's wall-clock figure counts the time the
 * thread waited for a core, this does not (it still counts the caches other work spoils). Runs
 * rounds of operations after a warm-up and prints each round and the median.
 */
public final class CpuRounds {

    private CpuRounds() {}

    /**
     * Runs {@code warmUp} operations, then {@code rounds} rounds of {@code perRound}, and prints the
     * CPU time and the bytes allocated per operation, labelled {@code what}.
     */
    public static void run(String what, LongSupplier operation, int warmUp, int rounds, int perRound) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long sink = 0;
        for (int i = 0; i < warmUp; i++) {
            sink += operation.getAsLong();
        }
        double[] cpu = new double[rounds];
        double[] allocated = new double[rounds];
        long self = Thread.currentThread().getId();
        for (int r = 0; r < rounds; r++) {
            long cpuBefore = threads.getCurrentThreadCpuTime();
            long bytesBefore = threads.getThreadAllocatedBytes(self);
            for (int i = 0; i < perRound; i++) {
                sink += operation.getAsLong();
            }
            cpu[r] = (threads.getCurrentThreadCpuTime() - cpuBefore) / 1e6 / perRound;
            allocated[r] = (threads.getThreadAllocatedBytes(self) - bytesBefore) / 1e3 / perRound;
            System.out.printf("%s, round %d: %.3f ms of CPU, %.1f kB allocated%n", what, r + 1, cpu[r], allocated[r]);
        }
        double[] sorted = cpu.clone();
        Arrays.sort(sorted);
        System.out.printf("%s: median %.3f ms of CPU (min %.3f, max %.3f), %.1f kB allocated; load average %.2f"
                        + " (%d)%n", what, sorted[rounds / 2], sorted[0], sorted[rounds - 1], allocated[rounds - 1],
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), sink % 10);
    }
}
