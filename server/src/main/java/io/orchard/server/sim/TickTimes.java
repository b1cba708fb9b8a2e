package io.orchard.server.sim;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;

/**
 * A histogram of how long the simulation's thread works on each tick, cheap enough to keep always
 * on: one counter per 10 µs up to 200 ms, one for everything longer, and the maximum. The tick thread records; any thread
 * reads a {@link TickStats} summary or resets it (a reading that overlaps a reset may mix the two).
 */
final class TickTimes {

    private static final long BUCKET_NANOS = 10_000;
    private static final int BUCKETS = 20_000;

    private final AtomicLongArray counts = new AtomicLongArray(BUCKETS + 1);
    private final AtomicLong ticks = new AtomicLong();
    private final AtomicLong late = new AtomicLong();
    private final AtomicLong max = new AtomicLong();

    /** Records one tick's work; {@code late} says it started more than a tick behind its schedule. */
    void record(long workNanos, boolean lateStart) {
        int bucket = (int) Math.min(BUCKETS, Math.max(0, workNanos) / BUCKET_NANOS);
        counts.incrementAndGet(bucket);
        ticks.incrementAndGet();
        if (lateStart) {
            late.incrementAndGet();
        }
        long previous;
        while (workNanos > (previous = max.get()) && !max.compareAndSet(previous, workNanos)) {
            // another reset or record raced us: read again
        }
    }

    void reset() {
        for (int i = 0; i <= BUCKETS; i++) {
            counts.set(i, 0);
        }
        ticks.set(0);
        late.set(0);
        max.set(0);
    }

    TickStats stats() {
        long total = ticks.get();
        return new TickStats(total, quantile(total, 0.50), quantile(total, 0.99), Duration.ofNanos(max.get()),
                late.get());
    }

    /** The upper edge of the bucket holding the quantile, capped at the maximum seen. */
    private Duration quantile(long total, double q) {
        if (total == 0) {
            return Duration.ZERO;
        }
        long rank = (long) Math.ceil(q * total);
        long seen = 0;
        for (int i = 0; i <= BUCKETS; i++) {
            seen += counts.get(i);
            if (seen >= rank) {
                // The last bucket holds everything longer than the histogram: there the maximum is the best bound.
                return Duration.ofNanos(i == BUCKETS ? max.get()
                        : Math.min((i + 1) * BUCKET_NANOS, Math.max(max.get(), BUCKET_NANOS)));
            }
        }
        return Duration.ofNanos(max.get());
    }
}
