package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * How the server's simulation clock advances.
 * <ul>
 * <li>{@link #REALTIME}: ticks follow the wall clock; an agent that is late misses the tick.
 * <li>{@link #LOCKSTEP}: a tick advances as soon as every agent has ended its turn (or the per-tick
 * deadline passes), so a seed and a sequence of actions always give the same game.
 * </ul>
 */
public enum ClockMode {
    /** Ticks follow the wall clock. */
    REALTIME("realtime"),

    /** A tick advances when every agent has ended its turn. */
    LOCKSTEP("lockstep");

    private final String wireName;

    ClockMode(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
