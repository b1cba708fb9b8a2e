package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * Where the game is in its life, as a client that connects learns it from the {@code Welcome}.
 */
public enum GamePhase {
    /** Waiting for enough agents, or for a start command: no ticks pass yet. */
    WAITING("waiting"),

    /** Ticks pass. */
    RUNNING("running"),

    /** Paused by a command: no ticks pass until it is resumed. */
    PAUSED("paused"),

    /** The fruit is gone or the time is up. */
    OVER("over");

    private final String wireName;

    GamePhase(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
