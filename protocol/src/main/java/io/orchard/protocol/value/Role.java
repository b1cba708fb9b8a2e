package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * What a client is, as it says in its hello: an agent control client or a viewer.
 */
public enum Role {
    /** A control client that registers and drives agents. */
    AGENT("agent"),

    /** A viewer that renders the world; it receives the snapshot and every change after it. */
    VIEWER("viewer");

    private final String wireName;

    Role(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
