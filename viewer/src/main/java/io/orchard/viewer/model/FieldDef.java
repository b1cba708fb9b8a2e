package io.orchard.viewer.model;

/**
 * One field of a node type: its name, type, who may read or write it, its default value, and for
 * node-valued fields the kind of node it accepts.
 */
public record FieldDef(String name, FieldType type, Access access, Object defaultValue,
                       NodeKind accepts) {

    /** VRML97's four field categories (X3D's initializeOnly/inputOnly/outputOnly/inputOutput). */
    public enum Access {
        FIELD, EXPOSED, EVENT_IN, EVENT_OUT;

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
