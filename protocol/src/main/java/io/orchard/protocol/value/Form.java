package io.orchard.protocol.value;

import java.util.Arrays;
import java.util.Collection;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/**
 * A form of the server's lines that a client may ask for by name in its {@code Hello}
 * ({@code reads}, version 2) besides the ordinary ones. A server ignores the names it does not
 * know, so a newer client may name forms an older server lacks; it then gets the ordinary lines.
 */
public enum Form {
    /**
     * Each perception in one {@code LeanPerception} line, numbers in centimetres and milliradians,
     * in place of {@code Perception}, {@code LandmarkPerception} and {@code CastlePerception}; and
     * no {@code ActionResult} for an accepted {@code Move}, which the next perception shows.
     */
    LEAN_PERCEPTION("LeanPerception"),

    /** With {@link #LEAN_PERCEPTION}: an accepted {@code Move} is answered with its {@code ActionResult} all the same. */
    ACCEPTED_MOVES("AcceptedMoves");

    private final String wireName;

    Form(String wireName) {
        this.wireName = wireName;
    }

    /** The name of this form in {@code Hello.reads}. */
    public String wireName() {
        return wireName;
    }

    /** The forms these names ask for, ignoring names no form has; empty for null. */
    public static Set<Form> named(Collection<String> names) {
        Set<Form> forms = EnumSet.noneOf(Form.class);
        if (names != null) {
            for (Form form : values()) {
                if (names.contains(form.wireName)) {
                    forms.add(form);
                }
            }
        }
        return forms;
    }

    /** The names of these forms, in the order of this enum, for {@code Hello.reads}. */
    public static List<String> names(Set<Form> forms) {
        return Arrays.stream(values()).filter(forms::contains).map(Form::wireName).toList();
    }
}
