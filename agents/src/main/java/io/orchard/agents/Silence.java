package io.orchard.agents;

import java.time.Duration;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * How long the agent has sent the server nothing, and the "still here" that breaks a long silence.
 * A controller with nothing to say (it waits for an instruction, or was told to stop) must still
 * send a {@code KeepAlive} before the server's idle rule closes its connection (after 120 s by
 * default, docs/protocol.md section 12): one is due after {@link #EVERY} of silence. The silence is
 * watched on a timer thread, not on the controller's, so that a controller busy for a while with a
 * long decision keeps its connection too. One daemon thread watches every controller of the JVM.
 */
final class Silence {

    /** The silence after which a keep-alive is due: well within the server's idle timeout. */
    static final Duration EVERY = Duration.ofSeconds(30);

    private static final ScheduledExecutorService WATCH = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread thread = new Thread(task, "orchard-keep-alive");
        thread.setDaemon(true);
        return thread;
    });

    private volatile long every = EVERY.toNanos();
    private volatile long lastSent = System.nanoTime();
    private ScheduledFuture<?> watching;

    /** Keep-alives after {@code silence} instead of {@link #EVERY}, for a server with a shorter idle rule. */
    void every(Duration silence) {
        if (silence.isNegative() || silence.isZero()) {
            throw new IllegalArgumentException("the silence before a keep-alive must be positive, was " + silence);
        }
        every = silence.toNanos();
    }

    /** Something was sent: the silence starts again. Safe from any thread. */
    void broken() {
        lastSent = System.nanoTime();
    }

    /** From now on, {@code stillHere} runs whenever the silence has lasted long enough, until {@link #unwatch()}. */
    synchronized void watch(Runnable stillHere) {
        broken();
        long period = Math.max(1, Math.min(TimeUnit.SECONDS.toMillis(1), TimeUnit.NANOSECONDS.toMillis(every) / 4));
        watching = WATCH.scheduleWithFixedDelay(() -> {
            if (System.nanoTime() - lastSent >= every) {
                stillHere.run();
                broken();
            }
        }, period, period, TimeUnit.MILLISECONDS);
    }

    /** No more keep-alives. */
    synchronized void unwatch() {
        if (watching != null) {
            watching.cancel(false);
        }
    }
}
