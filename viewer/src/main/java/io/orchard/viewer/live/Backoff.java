package io.orchard.viewer.live;

import java.time.Duration;

/**
 * How long a viewer waits before it connects again: {@code first} before the first retry, twice as
 * long before each next one, never longer than {@code most}.
 *
 * @param first the wait before the first retry
 * @param most  the longest wait
 */
public record Backoff(Duration first, Duration most) {

    /** Half a second at first, at most 10 s: a server restarted by hand is seen again within seconds. */
    public static final Backoff DEFAULT = new Backoff(Duration.ofMillis(500), Duration.ofSeconds(10));

    /** Checks the waits; a bad one is refused naming it. */
    public Backoff {
        if (first == null || first.isNegative() || first.isZero()) {
            throw new IllegalArgumentException("the first wait must be positive, was " + first);
        }
        if (most == null || most.compareTo(first) < 0) {
            throw new IllegalArgumentException("the longest wait must be at least the first, " + first + ", was "
                    + most);
        }
    }

    /** The wait before retry number {@code retry}, counted from 1. */
    public Duration before(int retry) {
        if (retry < 1) {
            throw new IllegalArgumentException("retries are counted from 1, was " + retry);
        }
        Duration wait = first;
        for (int i = 1; i < retry && wait.compareTo(most) < 0; i++) {
            wait = wait.multipliedBy(2);
        }
        return wait.compareTo(most) > 0 ? most : wait;
    }
}
