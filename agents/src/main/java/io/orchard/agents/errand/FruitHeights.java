package io.orchard.agents.errand;

import io.orchard.agents.language.Language;
import io.orchard.agents.language.Phrasing;
import io.orchard.agents.language.Place;
import io.orchard.agents.language.Reference;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Nullable;

/**
 * Whether the body can collect fruit at all where the words put it: a bunny, eating from the
 * ground, cannot take a coconut hanging in a tree however long it searches. The heights are the
 * world's rules (docs/agents.md): fruit lies on the ground with its centre 0.15 to 0.35 high, on
 * tables 0.85 to 1.35, and hangs in trees 1.5 to 3.0.
 */
final class FruitHeights {

    private FruitHeights() {}

    /** Heights of fruit centres in one kind of place, and where that is, in English and in German. */
    private record Band(String where, String wo, double low, double high) {}

    private static final Band GROUND = new Band("lies on the ground", "auf dem Boden liegen", 0.15, 0.35);
    private static final Band TABLE = new Band("lies on a table", "auf einem Tisch liegen", 0.85, 1.35);
    private static final Band TREE = new Band("hangs in a tree", "in einem Baum hängen", 1.5, 3.0);

    /**
     * Why the gripper cannot take any fruit the reference describes, in the language spoken; null when
     * it may.
     */
    static @Nullable String refusal(Reference what, Gripper gripper, Speech speech) {
        Band band = band(what.place());
        if (band == null || (gripper.maxHeight() >= band.low() && gripper.minHeight() <= band.high())) {
            return null;
        }
        boolean german = speech.language() == Language.GERMAN;
        String words = Phrasing.noun(what, speech.language(), Phrasing.Case.ACCUSATIVE);
        return speech.outOfReach(words, german ? band.wo() : band.where(), band.low(), band.high(), gripper);
    }

    private static Band band(@Nullable Place place) {
        if (place == null || place.anchor() == null && place.relation() != Place.Relation.ON_GROUND) {
            return null;
        }
        return switch (place.relation()) {
            case ON -> place.anchor().kind() == Reference.Kind.TABLE ? TABLE : null;
            case IN -> place.anchor().kind() == Reference.Kind.TREE ? TREE : null;
            case UNDER, ON_GROUND -> GROUND;
            default -> null;
        };
    }
}
