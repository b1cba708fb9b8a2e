package io.orchard.server.net;

import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;

/**
 * Logs a kind of warning at most once a second, saying how many were held back: a flood of bad
 * clients must not become a flood of log lines. Shared by the connections; safe from any thread.
 */
final class RareWarnings {

    private static final long SECOND = 1_000_000_000L;

    private final Logger log;
    private final AtomicLong last = new AtomicLong(System.nanoTime() - 2 * SECOND);
    private final AtomicLong held = new AtomicLong();

    RareWarnings(Logger log) {
        this.log = log;
    }

    /** Logs {@code format} with {@code arguments} unless a warning of this kind was logged less than a second ago. */
    void warn(String format, Object... arguments) {
        long now = System.nanoTime();
        long before = last.get();
        if (now - before > SECOND && last.compareAndSet(before, now)) {
            long others = held.getAndSet(0);
            log.warn(others == 0 ? format : format + " (and " + others + " more like it since the last warning)",
                    arguments);
        } else {
            held.incrementAndGet();
            log.debug(format, arguments);
        }
    }
}
