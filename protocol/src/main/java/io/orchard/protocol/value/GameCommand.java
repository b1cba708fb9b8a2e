package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * Commands that start, pause, continue and restart a game, for consoles and viewers.
 */
public enum GameCommand {
    /** Start the game now, without waiting for more agents. */
    START("start"),

    /** Pause the simulation clock. */
    PAUSE("pause"),

    /** Continue a paused game. */
    RESUME("resume"),

    /**
     * Version 2: end the game (if it is not over) and make a new one on the same server, of the
     * seed given or the same seed, which waits for its agents as a new server would.
     */
    RESTART("restart");

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
