package io.orchard.server.sim;

import java.time.Duration;

/**
 * How long the simulation's thread worked on its ticks since the server started (or since the
 * statistics were last reset): the time from the start of a tick's first half to the end of its
 * second, without the wait for clients in between. At 20 ticks per second a tick has 50 ms; work
 * near that means the server cannot hold its tick rate.
 *
 * @param ticks     ticks measured
 * @param p50       median work per tick (to 10 µs)
 * @param p99       99th percentile (to 10 µs)
 * @param max       the longest
 * @param lateTicks ticks that started more than a whole tick behind the realtime schedule
 */
public record TickStats(long ticks, Duration p50, Duration p99, Duration max, long lateTicks) {

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "%d ticks, work p50 %.2f ms, p99 %.2f ms, max %.2f ms, %d late",
                ticks, p50.toNanos() / 1e6, p99.toNanos() / 1e6, max.toNanos() / 1e6, lateTicks);
    }
}
