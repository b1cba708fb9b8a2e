package io.orchard.server;

import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Writes the checkpoints the simulation hands over, on a thread of their own so that a tick never
 * waits for the disk, one at a time and in the order they were taken; and asks for one on a timer.
 *
 * <p>The checkpoints taken whenever a fruit is collected can come every tick in a crowded game, and
 * a big world takes tens of milliseconds to write: those are {@linkplain #offer offered} instead,
 * and only the newest one is written, at most every {@link #MIN_INTERVAL_MILLIS} ms.
 */
public final class Checkpoints implements AutoCloseable {

    private static final Logger log = LoggerFactory.getLogger(Checkpoints.class);

    /** The shortest time between two writes of offered checkpoints. */
    static final long MIN_INTERVAL_MILLIS = 200;

    private final Path file;
    private final java.util.concurrent.atomic.AtomicReference<Checkpoint> newest =
            new java.util.concurrent.atomic.AtomicReference<>();
    private final java.util.concurrent.atomic.AtomicBoolean offerScheduled =
            new java.util.concurrent.atomic.AtomicBoolean();
    private volatile long lastOfferWritten;
    private final java.util.concurrent.ScheduledThreadPoolExecutor thread =
            new java.util.concurrent.ScheduledThreadPoolExecutor(1, task -> {
                Thread writer = new Thread(task, "orchard-checkpoint");
                writer.setDaemon(true);
                return writer;
            });

    /**
     * A writer of checkpoints to {@code file}, the game's checkpoint file, or to none (null): then
     * only checkpoints written to a file named with them are.
     */
    public Checkpoints(Path file) {
        this.file = file;
        this.lastOfferWritten = System.nanoTime() - MIN_INTERVAL_MILLIS * 1_000_000;
    }

    /** The game's checkpoint file, or null. */
    public Path file() {
        return file;
    }

    /** Runs {@code request} every {@code interval}, from one interval from now. */
    public void every(Duration interval, Runnable request) {
        long millis = interval.toMillis();
        thread.scheduleAtFixedRate(request, millis, millis, TimeUnit.MILLISECONDS);
    }

    /** Writes the checkpoint to {@code to}, then completes {@code done} (if any) with the file or the failure. */
    public void write(Checkpoint checkpoint, Path to, CompletableFuture<Path> done) {
        try {
            thread.execute(() -> writeNow(checkpoint, to, done));
        } catch (java.util.concurrent.RejectedExecutionException e) {
            if (done != null) {
                done.completeExceptionally(new IOException("the server is closing", e));
            }
        }
    }

    private void writeNow(Checkpoint checkpoint, Path to, CompletableFuture<Path> done) {
        try {
            CheckpointFile.write(checkpoint, to);
            log.debug("checkpoint of tick {} written to {}", checkpoint.tick(), to);
            if (done != null) {
                done.complete(to);
            }
        } catch (IOException | RuntimeException e) {
            log.warn("cannot write the checkpoint to {}: {}", to, e.toString());
            if (done != null) {
                done.completeExceptionally(e);
            }
        }
    }

    /**
     * Writes {@code checkpoint} to the server's file soon, unless a newer one is offered before it is
     * written: then only the newer one is.
     */
    public void offer(Checkpoint checkpoint) {
        newest.set(checkpoint);
        if (offerScheduled.compareAndSet(false, true)) {
            long wait = Math.max(0, lastOfferWritten + MIN_INTERVAL_MILLIS * 1_000_000 - System.nanoTime());
            try {
                thread.schedule(this::writeNewest, wait, TimeUnit.NANOSECONDS);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                offerScheduled.set(false); // closing
            }
        }
    }

    private void writeNewest() {
        offerScheduled.set(false);
        Checkpoint checkpoint = newest.getAndSet(null);
        if (checkpoint != null) {
            lastOfferWritten = System.nanoTime();
            // Already on the writer's thread, and perhaps after close() has begun: a new task would be refused.
            writeNow(checkpoint, file, null);
        }
    }

    /** Writes what was handed over already, then ends the thread. */
    @Override
    public void close() {
        thread.setExecuteExistingDelayedTasksAfterShutdownPolicy(true);
        thread.shutdown();
        try {
            thread.awaitTermination(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
