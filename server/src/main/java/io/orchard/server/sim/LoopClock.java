package io.orchard.server.sim;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * The time a {@link TickLoop} keeps: it reads it, sleeps in it until a tick is due, and waits in it
 * for what clients send up to a deadline. The server runs on {@link #SYSTEM}; a test's clock moves
 * only when the loop sleeps or waits for nothing, so that a test steps the loop with no real time
 * passing.
 */
interface LoopClock {

    /** The system's monotonic clock, and real sleeping and waiting. */
    LoopClock SYSTEM = new LoopClock() {
        @Override
        public long nanoTime() {
            return System.nanoTime();
        }

        @Override
        public void sleep(long nanos) throws InterruptedException {
            LockSupport.parkNanos(nanos);
            if (Thread.interrupted()) {
                throw new InterruptedException();
            }
        }

        @Override
        public <T> T poll(BlockingQueue<T> queue, long millis) throws InterruptedException {
            return queue.poll(millis, TimeUnit.MILLISECONDS);
        }
    };

    /** Now, in nanoseconds from an arbitrary origin, as {@link System#nanoTime()}. */
    long nanoTime();

    /** Lets up to {@code nanos} pass (less when the thread is woken early). */
    void sleep(long nanos) throws InterruptedException;

    /** Takes the head of {@code queue}, waiting up to {@code millis} for one to come; null when none came. */
    <T> T poll(BlockingQueue<T> queue, long millis) throws InterruptedException;
}
