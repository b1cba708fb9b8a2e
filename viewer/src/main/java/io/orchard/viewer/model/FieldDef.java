package io.orchard.viewer.model;

/**
 * One field of a node type: its name, type, who may read or write it, its default value, and for
 * node-valued fields the kind of node it accepts.
 */
public record FieldDef(String name, FieldType type, Access access, Object defaultValue,
                       NodeKind accepts) {

    /** VRML97's four field categories (X3D's initializeOnly/inputOnly/outputOnly/inputOutput). */
    public enum Access {
        /** A value set in the file only: VRML97 {@code field}, X3D {@code initializeOnly}. */
        FIELD,
        /** Set in the file, receives and sends events: {@code exposedField}, {@code inputOutput}. */
        EXPOSED,
        /** Receives events only: {@code eventIn}, {@code inputOnly}. */
        EVENT_IN,
        /** Sends events only: {@code eventOut}, {@code outputOnly}. */
        EVENT_OUT;

        /** Whether a file may give the field a value: true for fields and exposed fields. */
        public boolean canInitialize() {
            return this == FIELD || this == EXPOSED;
        }

        boolean canReceive() {
            return this == EXPOSED || this == EVENT_IN;
        }

        boolean canSend() {
            return this == EXPOSED || this == EVENT_OUT;
        }
    }
}
