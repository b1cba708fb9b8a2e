package io.orchard.server.sim;

import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import java.util.function.LongSupplier;

/**
 * Agents whose connection dropped, kept so that their controllers can get them back with their
 * resume tokens. For a while after an agent left (the reservation, {@link #DEFAULT_RESERVATION}
 * unless set otherwise) its name, and with it its score, is its controller's alone: anyone else
 * who registers the name is refused. The while is measured on the wall clock, since it is a
 * controller's reconnecting that it waits for, which takes as long in a paused game as in a
 * running one. Used on the simulation's thread only.
 */
final class Departures {

    /** How long a dropped agent's name stays reserved unless the server is set up otherwise. */
    static final Duration DEFAULT_RESERVATION = Duration.ofSeconds(60);

    private record Departed(Checkpoint.SavedAgent agent, long left, long until) {}

    private final Map<String, Departed> byName = new HashMap<>();
    private long reservationNanos = DEFAULT_RESERVATION.toNanos();

    /** The wall clock, in nanoseconds as {@link System#nanoTime()}; a test's own in tests. */
    LongSupplier clock = System::nanoTime;

    /** Reserves the names of agents that leave from now on for {@code time}; zero frees them at once. */
    void reserveFor(Duration time) {
        if (time == null || time.isNegative()) {
            throw new IllegalArgumentException("the reservation of a dropped agent's name must be zero or more, was "
                    + time);
        }
        reservationNanos = time.toNanos();
    }

    /** An agent left: it is kept, and its name reserved from now. */
    void left(Checkpoint.SavedAgent agent) {
        long now = clock.getAsLong();
        byName.put(agent.name(), new Departed(agent, now, now + reservationNanos));
    }

    /** The agent of that name that left, if one did. */
    Checkpoint.SavedAgent of(String name) {
        Departed departed = byName.get(name);
        return departed == null ? null : departed.agent();
    }

    /** Forgets the agent of that name: it is back, or the name went to someone else. */
    void forget(String name) {
        byName.remove(name);
    }

    /**
     * Why the name is not free for someone without the agent's token, or null when it is free: no
     * agent of that name left, or its reservation is over.
     */
    String whyReserved(String name) {
        Departed departed = byName.get(name);
        if (departed == null) {
            return null;
        }
        long now = clock.getAsLong();
        long left = departed.until() - now;
        if (left <= 0) {
            return null;
        }
        return "agent '" + name + "' left " + (now - departed.left()) / 1_000_000_000L + " s ago and its name "
                + "and score are kept for its controller, who gets them back by registering it with its resumeToken; the name "
                + "frees up in " + (left + 999_999_999L) / 1_000_000_000L + " s";
    }
}
