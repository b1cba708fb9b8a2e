package io.orchard.server.bench;

import com.sun.management.OperatingSystemMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.util.HashMap;
import java.util.Map;

/**
 * CPU time of this JVM's threads, grouped by what they do as their names say: the simulation's
 * thread ({@code orchard-tick}), the server's other threads ({@code orchard-}: network I/O), the
 * load generator's clients ({@code loadgen}) and the rest (the JVM's own: garbage collector,
 * compiler). A snapshot; {@link #since} gives the seconds used between two.
 */
final class ThreadCpu {

    /** Seconds of CPU by group: tick, server I/O, clients, other Java threads; and the whole process. */
    record Used(double tick, double io, double clients, double otherJava, double process) {}

    private final Map<Long, Long> byThread;
    private final long process;

    private ThreadCpu(Map<Long, Long> byThread, long process) {
        this.byThread = byThread;
        this.process = process;
    }

    static ThreadCpu now() {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        Map<Long, Long> cpu = new HashMap<>();
        for (long id : threads.getAllThreadIds()) {
            long used = threads.getThreadCpuTime(id);
            if (used >= 0) {
                cpu.put(id, used);
            }
        }
        return new ThreadCpu(cpu, ((OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime());
    }

    /** What each group used from {@code before} to this snapshot. */
    Used since(ThreadCpu before) {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        double tick = 0;
        double io = 0;
        double clients = 0;
        double other = 0;
        long[] ids = byThread.keySet().stream().mapToLong(Long::longValue).toArray();
        for (ThreadInfo info : threads.getThreadInfo(ids)) {
            if (info == null) {
                continue;
            }
            double used = (byThread.get(info.getThreadId()) - before.byThread.getOrDefault(info.getThreadId(), 0L)) / 1e9;
            String name = info.getThreadName();
            if (name.startsWith("orchard-tick")) {
                tick += used;
            } else if (name.startsWith("orchard-")) {
                io += used;
            } else if (name.startsWith("loadgen")) {
                clients += used;
            } else {
                other += used;
            }
        }
        return new Used(tick, io, clients, other, (process - before.process) / 1e9);
    }
}
