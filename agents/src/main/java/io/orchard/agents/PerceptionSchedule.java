package io.orchard.agents;

/**
 * When the agent's perceptions come, so that in lockstep mode the controller knows on a
 * {@code Tick} whether to wait for that tick's perception before deciding. A request sent during a
 * turn is applied at the end of that tick, so its first perception comes with the next tick and
 * then every {@code every} ticks; a request sent between ticks (at registration, before the game)
 * comes at a tick the controller cannot know, until the first one arrives.
 */
final class PerceptionSchedule {

    /** Whether a perception is due in a tick. */
    enum Expect {
        /** It will come: wait for it. */
        YES,
        /** It may come: wait a little. */
        MAYBE,
        /** None is due. */
        NO
    }

    private int every;
    private long phase = -1;
    private boolean once;

    /**
     * A request was sent.
     *
     * @param period    0 for one perception, N for one every N ticks
     * @param firstTick the tick its first perception comes in, or -1 when that is not known
     */
    void requested(int period, long firstTick) {
        every = period;
        once = period == 0;
        phase = firstTick;
    }

    /** A perception of {@code tick} came. */
    void perceived(long tick) {
        if (every > 0) {
            phase = tick;
        } else {
            once = false;
        }
    }

    /** Whether a perception is due in {@code tick}. */
    Expect expect(long tick) {
        if (every > 0) {
            if (phase < 0) {
                return Expect.MAYBE;
            }
            if (tick < phase) {
                return Expect.NO;
            }
            return (tick - phase) % every == 0 ? Expect.YES : Expect.NO;
        }
        if (!once) {
            return Expect.NO;
        }
        return phase < 0 ? Expect.MAYBE : tick == phase ? Expect.YES : Expect.NO;
    }
}
