package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;

/**
 * Standing still: until told otherwise (stop, wait here) or for a number of seconds (wait 10
 * seconds). A stopped agent sends no move at all, so that it stands still from the next tick on.
 */
final class Holding implements Pursuit {

    private final Kit kit;
    private final double seconds;
    private double until = Double.NaN;

    Holding(Kit kit, double seconds) {
        this.kit = kit;
        this.seconds = seconds;
    }

    @Override
    public Status step() {
        if (Double.isNaN(until)) {
            until = kit.motor.time() + seconds;
        }
        kit.standStill();
        return kit.motor.time() >= until ? Status.DONE : Status.RUNNING;
    }

    @Override
    public String outcome() {
        return kit.speech.doneWaiting();
    }
}
