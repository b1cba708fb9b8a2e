package io.orchard.agents;

/**
 * Keeps a client under the server's limit on the lines it sends (by default 2,000 a second, in
 * bursts of up to 4,000, measured in wall-clock time; a client beyond it is cut off). In lockstep
 * mode a game can run many times faster than real time, and an agent that acts and ends its turn
 * every tick would go over; the throttle makes it wait instead, which slows the clock down.
 */
final class Throttle {

    /** Lines per second, safely under the server's default of 2,000. */
    static final double RATE = 1800;

    /** Lines at once, safely under the server's default of 4,000. */
    static final double BURST = 3000;

    private final double rate;
    private final double burst;
    private double tokens;
    private long last = System.nanoTime();

    Throttle(double rate, double burst) {
        this.rate = rate;
        this.burst = burst;
        this.tokens = burst;
    }

    /** Takes one line's token, waiting until there is one. */
    synchronized void acquire() throws InterruptedException {
        refill();
        while (tokens < 1) {
            long waitNanos = (long) ((1 - tokens) / rate * 1e9) + 1;
            Thread.sleep(waitNanos / 1_000_000, (int) (waitNanos % 1_000_000));
            refill();
        }
        tokens -= 1;
    }

    private void refill() {
        long now = System.nanoTime();
        tokens = Math.min(burst, tokens + (now - last) / 1e9 * rate);
        last = now;
    }
}
