package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * What became of an action.
 */
public enum Outcome {
    /** The action was carried out as asked. */
    ACCEPTED("accepted"),

    /** A move was cut short by another agent; the result names it and where the agent stops. */
    BLOCKED("blocked"),

    /** The action was refused and changed nothing; the reason says why. */
    REJECTED("rejected");

    private final String wireName;

    Outcome(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
