package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * Commands that start, pause and continue a game, for consoles and viewers.
 */
public enum GameCommand {
    /** Start the game now, without waiting for more agents. */
    START("start"),

    /** Pause the simulation clock. */
    PAUSE("pause"),

    /** Continue a paused game. */
    RESUME("resume");

    private final String wireName;

    GameCommand(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
