package io.orchard.server.net;

import io.netty.channel.EventLoop;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Hands the writes of a tick to the I/O threads in one task per thread rather than one per client:
 * waking an I/O thread costs a system call, and a tick flushes every client at once. A write is
 * queued for its channel's thread, and the thread is woken only if no task of this kind is already
 * on its way. One per server, shared by its connections.
 */
final class TickWrites {

    /** The writes waiting for one I/O thread. */
    private static final class Pending implements Runnable {
        private final EventLoop loop;
        private final Queue<Runnable> writes = new ConcurrentLinkedQueue<>();
        private final AtomicBoolean scheduled = new AtomicBoolean();

        Pending(EventLoop loop) {
            this.loop = loop;
        }

        void add(Runnable write) {
            writes.add(write);
            if (scheduled.compareAndSet(false, true)) {
                loop.execute(this);
            }
        }

        @Override
        public void run() {
            // Cleared first: a write queued while these run schedules another round.
            scheduled.set(false);
            Runnable write;
            while ((write = writes.poll()) != null) {
                write.run();
            }
        }
    }

    private final Map<EventLoop, Pending> byLoop = new ConcurrentHashMap<>();

    /** Runs {@code write} on {@code loop}, soon, together with the other writes queued for it. */
    void submit(EventLoop loop, Runnable write) {
        byLoop.computeIfAbsent(loop, Pending::new).add(write);
    }
}
