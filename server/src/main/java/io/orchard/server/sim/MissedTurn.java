package io.orchard.server.sim;

import java.util.List;
import java.util.Locale;

/**
 * A turn that a lockstep game went on without: the client of these agents had not ended it
 * ({@code EndTurn}) when the game moved on. A recording that has none of these is the same, byte for
 * byte, every time the same agents play the same seed; one that has them says where the game may
 * part from another.
 *
 * @param tick   the tick whose turn was missed; 0 for the setup turn before the game started
 * @param agents the agents that client drives, by name
 * @param kind   which turn, and whether the game waited for it
 */
public record MissedTurn(long tick, List<String> agents, Kind kind) {

    /** Which turn was missed. */
    public enum Kind {
        /** The setup after registering: the game started without it when the deadline passed. */
        SETUP,
        /** A tick's turn: the tick waited until the deadline and ended without it. */
        DEADLINE,
        /**
         * A tick's turn while the client was late (it had missed several turns in a row): the tick
         * did not wait for it.
         */
        LATE;

        /** As a recording writes it: {@code setup}, {@code deadline} or {@code late}. */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /** Checks the components: a tick of 0 or more, a kind; the agents are copied. */
    public MissedTurn {
        if (tick < 0) {
            throw new IllegalArgumentException("tick must not be negative, was " + tick);
        }
        agents = List.copyOf(agents);
        if (kind == null) {
            throw new IllegalArgumentException("kind must be setup, deadline or late, was null");
        }
    }
}
