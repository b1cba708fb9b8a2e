package io.orchard.server.bench;

import java.util.concurrent.atomic.AtomicLongArray;

/**
 * Latencies recorded from many threads into 100 µs buckets up to 10 s, for percentiles that cost
 * one atomic increment to record. Values past the last bucket count in it.
 */
final class Latencies {

    private static final long BUCKET_NANOS = 100_000;
    private static final int BUCKETS = 100_000;

    private final AtomicLongArray counts = new AtomicLongArray(BUCKETS + 1);

    void record(long nanos) {
        counts.incrementAndGet((int) Math.min(BUCKETS, Math.max(0, nanos) / BUCKET_NANOS));
    }

    void reset() {
        for (int i = 0; i <= BUCKETS; i++) {
            counts.set(i, 0);
        }
    }

    long count() {
        long total = 0;
        for (int i = 0; i <= BUCKETS; i++) {
            total += counts.get(i);
        }
        return total;
    }

    /** The quantile {@code q} in milliseconds (the upper edge of its bucket); 0 when nothing was recorded. */
    double millis(double q) {
        long total = count();
        if (total == 0) {
            return 0;
        }
        long rank = (long) Math.ceil(q * total);
        long seen = 0;
        for (int i = 0; i <= BUCKETS; i++) {
            seen += counts.get(i);
            if (seen >= rank) {
                return (i + 1) * BUCKET_NANOS / 1e6;
            }
        }
        return BUCKETS * BUCKET_NANOS / 1e6;
    }
}
