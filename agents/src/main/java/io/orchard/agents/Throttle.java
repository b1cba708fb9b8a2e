package io.orchard.agents;

/**
 * Keeps a client under the server's limit on the lines it sends (by default 2,000 a second, in
 * bursts of up to 4,000, measured in wall-clock time, and 100 more for each tick of a lockstep
 * game; a client beyond it is cut off). A lockstep game runs many times faster than real time; the
 * lines each of its ticks allows ({@link #ticked()}) keep an agent that acts every tick within the
 * limit however fast the game goes, and the throttle makes one that sends more wait, which slows
 * the clock down.
 */
final class Throttle {

    /** Lines per second, safely under the server's default of 2,000. */
    static final double RATE = 1800;

    /** Lines at once, safely under the server's default of 4,000. */
    static final double BURST = 3000;

    /** Lines for each tick of a lockstep game, safely under the server's 100. */
    static final double PER_LOCKSTEP_TICK = 90;

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
        while (!tryAcquire()) {
            long waitNanos = (long) ((1 - tokens) / rate * 1e9) + 1;
            Thread.sleep(waitNanos / 1_000_000, (int) (waitNanos % 1_000_000));
        }
    }

    /** Takes one line's token if there is one now. */
    synchronized boolean tryAcquire() {
        refill();
        if (tokens < 1) {
            return false;
        }
        tokens -= 1;
        return true;
    }

    /** A tick of a lockstep game began: the server allows its lines. */
    synchronized void ticked() {
        tokens = Math.min(burst, tokens + PER_LOCKSTEP_TICK);
    }

    private void refill() {
        long now = System.nanoTime();
        tokens = Math.min(burst, tokens + (now - last) / 1e9 * rate);
        last = now;
    }
}
