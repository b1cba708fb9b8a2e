package io.orchard.server.sim;

import java.util.Random;

/**
 * The game's random generator: exactly {@link Random}'s sequence for the same seed, with a state
 * that can be read and set again, so that a checkpoint carries it and a resumed game draws what
 * the uninterrupted one would have drawn. Owned by the simulation's thread.
 */
final class GameRandom extends Random {

    private static final long MULTIPLIER = 0x5DEECE66DL;
    private static final long ADDEND = 0xBL;
    private static final long MASK = (1L << 48) - 1;

    private long state;

    GameRandom(long seed) {
        super(seed);
    }

    /** Continues from a state read with {@link #state()}. */
    void restore(long saved) {
        state = saved & MASK;
    }

    /** The whole state: 48 bits. */
    long state() {
        return state;
    }

    @Override
    public synchronized void setSeed(long seed) {
        // Called by Random's constructor: the same scrambling as Random's.
        state = (seed ^ MULTIPLIER) & MASK;
        super.setSeed(seed);
    }

    @Override
    protected int next(int bits) {
        state = (state * MULTIPLIER + ADDEND) & MASK;
        return (int) (state >>> (48 - bits));
    }
}
