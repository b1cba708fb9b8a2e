package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The throttle's tokens, counted with a rate so slow that the wall clock adds none during the test. */
class ThrottleTest {

    private static final double NEARLY_NEVER = 1e-9;

    private static int taken(Throttle throttle) {
        int taken = 0;
        while (throttle.tryAcquire()) {
            taken++;
        }
        return taken;
    }

    @Test
    void aBurstIsTakenAtOnceAndThenNothingMore() {
        Throttle throttle = new Throttle(NEARLY_NEVER, 20);
        assertThat(taken(throttle)).isEqualTo(20);
        assertThat(throttle.tryAcquire()).isFalse();
    }

    @Test
    void eachLockstepTickAllowsItsLinesUpToTheBurst() {
        Throttle throttle = new Throttle(NEARLY_NEVER, 200);
        taken(throttle);

        throttle.ticked();
        assertThat(taken(throttle)).isEqualTo((int) Throttle.PER_LOCKSTEP_TICK);
        throttle.ticked();
        throttle.ticked();
        throttle.ticked();
        assertThat(taken(throttle)).as("never more than the burst").isEqualTo(200);
    }
}
