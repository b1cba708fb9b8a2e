package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * How a viewer sizes and places an agent's model (version 2): fitted to the agent's body, the
 * default, or as its author made it.
 */
public enum ModelFit {
    /**
     * Scaled to the body's registered height and stood on the ground centred on the agent's place,
     * whatever the model's units and origin; the default.
     */
    BODY("body"),

    /** As authored: the model's own metres and origin, the agent's place at the model's origin. */
    AUTHORED("authored");

    private final String wireName;

    ModelFit(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
