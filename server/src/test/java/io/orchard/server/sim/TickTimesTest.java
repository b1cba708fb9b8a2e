package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.junit.jupiter.api.Test;

class TickTimesTest {

    private final TickTimes times = new TickTimes();

    @Test
    void percentilesAreTheUpperEdgesOfTheirTenMicrosecondBuckets() {
        for (int ms = 1; ms <= 100; ms++) {
            times.record(Duration.ofMillis(ms).toNanos() - 1, ms > 98);
        }
        TickStats stats = times.stats();
        assertThat(stats.ticks()).isEqualTo(100);
        assertThat(stats.p50()).isEqualTo(Duration.ofMillis(50));
        assertThat(stats.p99()).isEqualTo(Duration.ofMillis(99));
        assertThat(stats.max()).isEqualTo(Duration.ofMillis(100).minusNanos(1));
        assertThat(stats.lateTicks()).isEqualTo(2);
        assertThat(stats.toString()).contains("p50 50.00 ms", "p99 99.00 ms", "2 late");
    }

    @Test
    void aTickLongerThanTheHistogramCountsInItsLastBucketAndAsTheMaximum() {
        times.record(Duration.ofSeconds(3).toNanos(), true);
        assertThat(times.stats().max()).isEqualTo(Duration.ofSeconds(3));
        assertThat(times.stats().p99()).isEqualTo(Duration.ofSeconds(3));
    }

    @Test
    void aResetForgetsEverything() {
        times.record(5_000_000, false);
        times.reset();
        assertThat(times.stats()).isEqualTo(new TickStats(0, Duration.ZERO, Duration.ZERO, Duration.ZERO, 0));
    }
}
