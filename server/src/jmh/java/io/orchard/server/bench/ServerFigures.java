package io.orchard.server.bench;

import java.util.Locale;

/**
 * What the server did over a measured window: its ticks and the CPU its threads used, in seconds
 * of CPU. {@code process} is the whole server process, garbage collector and compiler included,
 * when the server runs in a process of its own; otherwise NaN, as it shares the JVM with the
 * clients.
 *
 * @param ticks   ticks that ran
 * @param p50     tick work, median, in ms
 * @param p99     tick work, 99th percentile, in ms
 * @param max     tick work, longest, in ms
 * @param late    ticks that started late
 * @param tick    CPU of the simulation's thread
 * @param io      CPU of the server's network threads
 * @param process CPU of the whole server process, or NaN
 */
record ServerFigures(long ticks, double p50, double p99, double max, long late, double tick, double io,
                     double process) {

    /** As one line of text, for a server process to hand its figures to the load generator. */
    String line() {
        return String.format(Locale.ROOT, "%d %s %s %s %d %s %s %s", ticks, p50, p99, max, late, tick, io, process);
    }

    /** Read back from {@link #line()}. */
    static ServerFigures parse(String line) {
        String[] f = line.trim().split(" ");
        return new ServerFigures(Long.parseLong(f[0]), Double.parseDouble(f[1]), Double.parseDouble(f[2]),
                Double.parseDouble(f[3]), Long.parseLong(f[4]), Double.parseDouble(f[5]), Double.parseDouble(f[6]),
                Double.parseDouble(f[7]));
    }
}
