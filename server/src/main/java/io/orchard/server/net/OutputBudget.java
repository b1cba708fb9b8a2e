package io.orchard.server.net;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The bytes waiting to be sent to all clients together, and the cap on them: when a client's
 * output takes the total past it, the client with the most waiting is cut off. What one client
 * may have waiting is capped too ({@link Outbox}), but a thousand clients each just under their own
 * cap would still be too much. Models shared between clients are not counted here: the
 * {@link ModelStore} caps them. Shared by every channel; safe from any thread.
 */
final class OutputBudget {

    private final long max;
    private final AtomicLong total = new AtomicLong();
    private final Set<Outbox> outboxes = ConcurrentHashMap.newKeySet();

    OutputBudget(long max) {
        this.max = max;
    }

    void opened(Outbox outbox) {
        outboxes.add(outbox);
    }

    void closed(Outbox outbox) {
        outboxes.remove(outbox);
    }

    /** Counts bytes that started (positive) or stopped (negative) waiting. */
    void add(long bytes) {
        if (total.addAndGet(bytes) > max && bytes > 0) {
            cutTheLargest();
        }
    }

    private synchronized void cutTheLargest() {
        if (total.get() <= max) {
            return;
        }
        Outbox largest = null;
        for (Outbox outbox : outboxes) {
            if (!outbox.isCut() && (largest == null || outbox.ownBytes() > largest.ownBytes())) {
                largest = outbox;
            }
        }
        if (largest != null) {
            largest.cutSoon("the server has " + total.get() + " bytes waiting for its clients, more than the "
                    + max + " it keeps, and this client has the most waiting: " + largest.ownBytes());
        }
    }

    /** Bytes waiting now. */
    long total() {
        return total.get();
    }
}
