package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * The kinds of regular world object that perception reports by relative position.
 * Trees and tables are approximated by their bounding cylinders, as in the paper.
 */
public enum ObjectKind {
    /** A tree: its trunk blocks movement, fruit may hang in its crown. */
    TREE("tree"),

    /** A table: it blocks movement, fruit may lie on its top. */
    TABLE("table");

    private final String wireName;

    ObjectKind(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
