package io.orchard.viewer.model;

import java.util.Map;
import java.util.Optional;

/**
 * A node type this loader knows: its fields and, for the XML encoding, the field a child element
 * of this type fills when it names none ({@code containerField}).
 */
public record NodeType(String name, NodeKind kind, String containerField,
                       Map<String, FieldDef> fields) {

    /** Copies the fields, so the type cannot change afterwards. */
    public NodeType {
        fields = Map.copyOf(fields);
    }

    /** The field named {@code fieldName}, or empty if the type has none of that name. */
    public Optional<FieldDef> field(String fieldName) {
        return Optional.ofNullable(fields.get(fieldName));
    }

    /**
     * The field an event sent to {@code eventName} arrives at: {@code set_translation} and
     * {@code translation} both reach the exposed field {@code translation}; {@code set_fraction}
     * is an eventIn of its own.
     */
    Optional<FieldDef> eventIn(String eventName) {
        FieldDef direct = fields.get(eventName);
        if (direct != null) {
            return direct.access().canReceive() ? Optional.of(direct) : Optional.empty();
        }
        if (eventName.startsWith("set_")) {
            FieldDef exposed = fields.get(eventName.substring(4));
            if (exposed != null && exposed.access() == FieldDef.Access.EXPOSED) {
                return Optional.of(exposed);
            }
        }
        return Optional.empty();
    }

    /** The field an event named {@code eventName} comes from: {@code translation_changed} too. */
    Optional<FieldDef> eventOut(String eventName) {
        FieldDef direct = fields.get(eventName);
        if (direct != null) {
            return direct.access().canSend() ? Optional.of(direct) : Optional.empty();
        }
        if (eventName.endsWith("_changed")) {
            FieldDef exposed = fields.get(eventName.substring(0, eventName.length() - 8));
            if (exposed != null && exposed.access() == FieldDef.Access.EXPOSED) {
                return Optional.of(exposed);
            }
        }
        return Optional.empty();
    }
}
