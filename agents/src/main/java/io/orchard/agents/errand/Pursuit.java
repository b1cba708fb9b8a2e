package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;

/**
 * One goal being pursued, a tick at a time. A pursuit says what it is doing when it has news
 * ("I don't know of a coconut yet; I'll look for one.") and, once it is over, how it went.
 */
interface Pursuit {

    /** One tick: RUNNING, or DONE or FAILED when it is over. */
    Status step();

    /** How it went, once {@link #step()} said it is over: "I'm at the castle." or why not. */
    String outcome();
}
