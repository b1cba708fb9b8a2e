package io.orchard.server.sim;

import java.util.concurrent.BlockingQueue;

/**
 * A clock that moves only when the loop sleeps, waits for nothing, or a test moves it: sleeping takes
 * no real time, and a wait for events takes what is queued at once or lets its whole timeout pass.
 */
final class FakeLoopClock implements LoopClock {

    private long now;

    @Override
    public long nanoTime() {
        return now;
    }

    @Override
    public void sleep(long nanos) {
        now += nanos;
    }

    @Override
    public <T> T poll(BlockingQueue<T> queue, long millis) {
        T head = queue.poll();
        if (head == null) {
            now += millis * 1_000_000;
        }
        return head;
    }

    /** Lets {@code millis} pass, as a tick that works that long would. */
    void advance(long millis) {
        now += millis * 1_000_000;
    }

    /** Milliseconds since the clock started. */
    long millis() {
        return now / 1_000_000;
    }
}
