package io.orchard.agents.language;

import static io.orchard.agents.language.Lexeme.Cat.DET;
import static io.orchard.agents.language.Lexeme.Cat.DIR;
import static io.orchard.agents.language.Lexeme.Cat.DIST;
import static io.orchard.agents.language.Lexeme.Cat.HERE;
import static io.orchard.agents.language.Lexeme.Cat.ME;
import static io.orchard.agents.language.Lexeme.Cat.NAME;
import static io.orchard.agents.language.Lexeme.Cat.NOUN;
import static io.orchard.agents.language.Lexeme.Cat.NUMBER;
import static io.orchard.agents.language.Lexeme.Cat.ORD;
import static io.orchard.agents.language.Lexeme.Cat.PREP;
import static io.orchard.agents.language.Lexeme.Cat.PRON;
import static io.orchard.agents.language.Lexeme.Cat.QUANT;
import static io.orchard.agents.language.Lexeme.Cat.SIDE;
import static io.orchard.agents.language.Lexeme.Cat.SIZE;
import static io.orchard.agents.language.Lexeme.Cat.UNIT;
import static io.orchard.agents.language.Lexeme.Cat.UNKNOWN;

import io.orchard.agents.language.Place.Relation;
import io.orchard.agents.language.Reference.Distance;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.language.Reference.Size;
import io.orchard.protocol.value.Sector;
import java.util.Locale;
import java.util.Optional;

/**
 * Noun phrases and the places they are in: "the three nearest bananas", "the coconut in the big
 * tree by the river", "the other side of the river", "it". Places attach to the nearest noun on
 * their left and nest through their anchors; pronouns and "one" refer to what the sentence named
 * before, which the {@link ParseContext} remembers.
 */
final class NounPhrases {

    private final ParseContext context;

    NounPhrases(ParseContext context) {
        this.context = context;
    }

    /**
     * A noun phrase: what it refers to and how many.
     *
     * @param ref           what it refers to; null only for the world and the ground
     * @param count         how many: a number as said (validated by the goal), or {@link Collect#ALL}
     * @param explicitCount whether a number or a quantity other than "a" was said ("three", "all")
     * @param world         whether it was "the world", "everywhere" or a bare "area": anywhere
     * @param ground        whether it was "the ground"
     * @param pronoun       whether it was "it", "them" or "him"
     */
    record Phrase(Reference ref, double count, boolean explicitCount, boolean world, boolean ground,
                  boolean pronoun) {
    }

    /** Whether a noun phrase can start with this word. */
    static boolean startsNounPhrase(Lexeme t) {
        return t.is(DET) || t.is(QUANT) || t.is(NUMBER) || t.is(SIZE) || t.is(DIST) || t.is(NOUN) || t.is(NAME)
                || t.is(PRON);
    }

    /** The noun phrase at the cursor, or null (with the cursor unmoved) when there is none. */
    Phrase phrase(Cursor c, boolean namesAllowed) {
        int start = c.position();
        Parts parts = new Parts();
        quantity(c, parts);
        modifiers(c, parts);
        if (!head(c, parts, start, namesAllowed)) {
            c.seek(start);
            return null;
        }
        postModifiers(c, parts);
        return parts.phrase();
    }

    /** The parts of a noun phrase read so far. */
    private final class Parts {

        Double number;
        boolean all;
        boolean some;
        Size size;
        Distance distance;
        boolean any;
        Lexeme head;
        Reference ref;
        boolean plural;
        boolean world;
        boolean ground;
        boolean area;
        Place place;
        Integer ordinal;
        Discourse.Mention pointed;

        Phrase phrase() {
            if (area) {
                if (place == null) {
                    world = true; // "the area": anywhere
                } else {
                    ref = Reference.place(place);
                }
            } else if (ref != null && place != null && ref.kind() != Kind.PLACE) {
                ref = ref.withPlace(place);
            }
            if (ref != null && pointed != null && ref.kind() == pointed.kind()) {
                ref = pointed.reference().withPlace(ref.place()); // "that table": the one the agent spoke of
            }
            if (ref != null) {
                ref = ref.withSize(size != null ? size : ref.size())
                        .withDistance(distance != null ? distance : ref.distance());
                if (ordinal != null) {
                    if (ref.size() == Size.LARGEST || ref.size() == Size.SMALLEST) {
                        throw Refusal.answer(context.answers.ORDINAL_HOW);
                    }
                    ref = ref.withOrdinal(ordinal, ref.distance() != null ? ref.distance() : Distance.NEAREST);
                }
            }
            double count;
            if (all) {
                count = Collect.ALL;
            } else if (number != null) {
                count = number;
            } else if (some) {
                count = 3;
            } else if (distance != null || ordinal != null || size == Size.LARGEST || size == Size.SMALLEST
                    || picked(place)) {
                count = 1;
            } else {
                count = plural && (!any || head.raw().toLowerCase(Locale.ROOT).endsWith("s")) ? Collect.ALL : 1;
            }
            boolean explicit = number != null && number != 1 || all || some;
            boolean pronoun = head != null && head.is(PRON) && !head.is(PRON, "one");
            return new Phrase(world || ground ? null : ref, count, explicit, world, ground, pronoun);
        }
    }

    /** Determiners and quantities: "the", "a", "all the", "every", "three of the", "some". */
    private void quantity(Cursor c, Parts parts) {
        while (!c.atEnd()) {
            Lexeme t = c.peek();
            if (t.is(DET)) {
                c.next();
                Discourse.Mention pointed = demonstrative(t, c);
                if (pointed != null) {
                    parts.pointed = pointed;
                }
                if (t.is(DET, "a") && parts.number == null) {
                    if (t.raw().equalsIgnoreCase("any")) {
                        parts.any = true; // "any banana" is one, "any bananas" all that are found
                    } else {
                        parts.number = 1.0;
                    }
                }
            } else if (t.is(QUANT, "everything")) {
                return; // the head
            } else if (t.is(QUANT)) {
                c.next();
                switch (t.lemma()) {
                    case "both" -> parts.number = 2.0;
                    case "some" -> parts.some = true;
                    default -> parts.all = true;
                }
                if (c.peekIs(PREP, "of")) {
                    c.next();
                }
            } else if (t.is(NUMBER) && !(t.number() == 1 && isHeadOne(c))) {
                c.next();
                parts.number = t.number();
                if (c.peekIs(PREP, "of")) {
                    c.next();
                }
            } else {
                return;
            }
        }
    }

    /**
     * "That table", "those trees": the person points at something the agent cannot see them point
     * at. It is the one of that kind the sentence named before, else the last the agent spoke about
     * or looked at (the {@link Discourse}); with neither, the agent asks rather than guess.
     *
     * @return the thing the agent spoke about, when that is what is meant; null otherwise
     */
    private Discourse.Mention demonstrative(Lexeme det, Cursor c) {
        Lexeme next = c.peek();
        if (!(det.raw().equalsIgnoreCase("that") || det.raw().equalsIgnoreCase("those")) || next == null
                || !next.is(NOUN) || Kind.ofWireName(next.lemma()) == null) {
            return null;
        }
        Reference antecedent = context.antecedent;
        Kind kind = Kind.ofWireName(next.lemma());
        if (antecedent != null && antecedent.kind() == kind) {
            return null;
        }
        return context.discourse.last(kind).filter(m -> m.kind() == kind || kind == Kind.FRUIT)
                .orElseThrow(() -> Refusal.answer(String.format(context.answers.DEMONSTRATIVE, det.raw() + " " + next.raw())));
    }

    /** Whether a place picks out one object of those that fit: "the fruit closest to the bridge". */
    private boolean picked(Place place) {
        return place != null && (place.relation() == Relation.CLOSEST_TO
                || place.relation() == Relation.FARTHEST_FROM);
    }

    /** Sizes, distances, ordinals and a late number: "the nearest two big", "the second". */
    private void modifiers(Cursor c, Parts parts) {
        while (!c.atEnd() && (c.peek().is(SIZE) || c.peek().is(DIST) || c.peek().is(ORD) || isSecond(c)
                || (c.peek().is(NUMBER) && parts.number == null && !isHeadOne(c)))) {
            Lexeme t = c.next();
            if (t.is(ORD)) {
                parts.ordinal = (int) Math.min(Integer.MAX_VALUE, t.number());
                if (parts.ordinal < 1 || parts.ordinal > Reference.MAX_ORDINAL) {
                    throw Refusal.answer(context.answers.ORDINAL_HOW);
                }
            } else if (t.is(UNIT, "second")) {
                parts.ordinal = 2;
            } else if (t.is(SIZE)) {
                parts.size = Size.valueOf(t.lemma().toUpperCase(Locale.ROOT));
            } else if (t.is(DIST)) {
                parts.distance = Distance.valueOf(t.lemma().toUpperCase(Locale.ROOT));
            } else {
                parts.number = t.number(); // "the nearest two bananas"
            }
        }
    }

    /** The head: a noun, a name, a pronoun, a place; false when there is no noun phrase here. */
    private boolean head(Cursor c, Parts parts, int start, boolean namesAllowed) {
        Lexeme head = c.peek();
        parts.head = head;
        if (head == null) {
            // no head: decided below
        } else if (head.is(QUANT, "everything")) {
            c.next();
            parts.ref = Reference.to(Kind.FRUIT);
            parts.all = true;
        } else if (head.is(NOUN)) {
            c.next();
            parts.plural = head.plural();
            switch (head.lemma()) {
                case "world" -> parts.world = true;
                case "ground" -> parts.ground = true;
                case "place" -> parts.area = true;
                default -> parts.ref = Reference.to(Kind.ofWireName(head.lemma()));
            }
        } else if (head.is(NAME)) {
            c.next();
            parts.ref = Reference.agent(head.lemma());
        } else if (head.is(UNKNOWN) && head.capitalised() && namesAllowed) {
            c.next();
            context.namesTaken.add(head.position());
            parts.ref = Reference.agent(head.raw());
        } else if (head.is(PRON)) {
            c.next();
            parts.ref = pronoun(head);
            parts.plural = head.is(PRON, "them") || head.is(PRON, "one") && head.raw().endsWith("s");
        } else if (head.is(NUMBER) && head.number() == 1) {
            c.next();
            parts.ref = oneOf(); // "the big one"
        } else if (head.is(DIR) && (c.position() > start || c.peekAt(1) == null || c.peekAt(1).is(PREP, "of"))) {
            c.next();
            parts.ref = Reference.place(compass(head, c)); // "the north", "the north of the castle"
        } else if (isRelation(head) && c.position() == start) {
            parts.ref = Reference.place(place(c)); // "near the castle", "the other side of the river"
        }
        if (parts.ref != null || parts.world || parts.ground || parts.area) {
            return true;
        }
        if (parts.number == null && !parts.all && !parts.some && parts.size == null && parts.distance == null) {
            return false;
        }
        parts.ref = oneOf(); // "the biggest", "collect all", "that one"
        return true;
    }

    /** What follows the head: its place, "nearest to the castle", "there", "all", "over there". */
    private void postModifiers(Cursor c, Parts parts) {
        while (!c.atEnd()) {
            Lexeme m = c.peek();
            Lexeme next = c.peekAt(1);
            Reference antecedent = context.antecedent;
            if (m.is(DET) && next != null && (isRelation(next) || next.is(DIR) || next.is(DIST))) {
                c.next(); // "that" of "the banana that is on the table"
            } else if (m.is(DIST) && (next == null || next.is(ME) || next.isAny(PREP, "to", "near", "from")
                    || (parts.place == null && (next.is(DET) || next.is(NOUN) || next.is(NAME))
                    && (m.is(DIST, "nearest") || m.is(DIST, "farthest"))))) {
                c.next();
                Distance distance = Distance.valueOf(m.lemma().toUpperCase(Locale.ROOT));
                if (c.peekIs(PREP, "to") || c.peekIs(PREP, "near") || c.peekIs(PREP, "from")) {
                    c.next();
                }
                if (c.peek() != null && c.peek().is(ME)) {
                    c.next(); // "the tree closest to me": measured from the agent anyway
                    parts.distance = distance;
                } else if (!c.atEnd() && parts.place == null && (distance == Distance.NEAREST
                        || distance == Distance.FARTHEST)) {
                    // "the fruit closest to the bridge": measured from the bridge, not from the agent
                    parts.place = Place.of(distance == Distance.NEAREST ? Relation.CLOSEST_TO : Relation.FARTHEST_FROM,
                            requiredAnchor(c));
                } else {
                    parts.distance = distance;
                }
            } else if (parts.place == null && isRelation(m) && (m.isAny(PREP, "on-ground", "beyond", "this-side",
                    "on-left", "on-right", "in-front", "behind-me", "near-me")
                    || (next != null && (startsNounPhrase(next) || next.is(DIR) || next.is(UNKNOWN))))) {
                parts.place = place(c);
            } else if (parts.place == null && m.isAny(SIDE, "left", "right") && m.raw().contains(" your ")) {
                c.next(); // "the banana on your left"
                parts.place = Place.of(m.is(SIDE, "left") ? Relation.LEFT : Relation.RIGHT, null);
            } else if (parts.place == null && m.is(DIR) && (next == null || next.is(PREP, "of") || !next.is(NOUN))) {
                c.next();
                parts.place = compass(m, c);
            } else if (parts.place == null && m.is(HERE, "there") && antecedent != null && !antecedent.isFruit()
                    && antecedent.kind() != Kind.PLACE) {
                c.next();
                parts.place = Place.of(Relation.NEAR, antecedent); // "go to the castle, collect the bananas there"
            } else if (m.is(QUANT, "all") || m.is(QUANT, "both")) {
                c.next(); // "them all", "them both"
                if (m.is(QUANT, "all")) {
                    parts.all = true;
                } else {
                    parts.number = 2.0;
                }
            } else if (m.is(HERE) && !m.is(HERE, "home")) {
                c.next(); // "the banana over there"
            } else {
                return;
            }
        }
    }

    /** Whether the "second" at the cursor is an ordinal ("the second tree") rather than a unit of time. */
    private boolean isSecond(Cursor c) {
        Lexeme next = c.peekAt(1);
        return c.peekIs(UNIT, "second") && next != null && (next.is(NOUN) || next.is(SIZE) || next.is(DIST)
                || next.is(PRON, "one"));
    }

    /** Whether the "one" at the cursor is the head of its phrase ("the big one") rather than a count. */
    private boolean isHeadOne(Cursor c) {
        Lexeme next = c.peekAt(1);
        return next == null || !(next.is(NOUN) || next.is(SIZE) || next.is(DIST) || next.is(PREP, "of")
                || next.is(NAME));
    }

    /** What "one" or a phrase without a noun refers to: the kind said before, else any fruit. */
    Reference oneOf() {
        if (context.antecedent != null && context.antecedent.kind() != Kind.PLACE) {
            return new Reference(context.antecedent.kind(), context.antecedent.name(), null, null, null);
        }
        return Reference.to(Kind.FRUIT);
    }

    private Reference pronoun(Lexeme word) {
        if (word.is(PRON, "one")) {
            return oneOf();
        }
        if (context.antecedent == null) {
            // nothing named in the sentence: what the agent spoke of last, fruit when fruit is wanted
            Optional<Discourse.Mention> spoken = word.is(PRON, "him") ? context.discourse.last(Kind.AGENT)
                    : context.answers.CAN_COLLECT.equals(context.hint) ? context.discourse.last(Kind.FRUIT)
                    : context.discourse.last();
            if (spoken.isPresent()) {
                return spoken.get().reference();
            }
        }
        if (context.antecedent == null || (word.is(PRON, "him") && context.antecedent.kind() != Kind.AGENT)) {
            throw Refusal.answer(context.answers.pronoun(word.raw(), context.question));
        }
        return context.antecedent;
    }

    static boolean isRelation(Lexeme t) {
        return t.isAny(PREP, "on", "on-ground", "in", "under", "from", "near", "by", "at", "around", "via", "beyond",
                "across", "over", "through", "this-side", "on-left", "on-right", "in-front", "behind-me", "near-me");
    }

    /** The place introduced by the relation word at the cursor. */
    Place place(Cursor c) {
        Lexeme relation = c.next();
        switch (relation.lemma()) {
            case "on-ground":
                return Place.onGround();
            case "beyond":
            case "across":
            case "over":
            case "through":
                return Place.of(Relation.BEYOND, anchorOrRiver(c));
            case "this-side":
                return Place.of(Relation.THIS_SIDE_OF, anchorOrRiver(c));
            case "on-left":
                return Place.of(Relation.LEFT, null);
            case "on-right":
                return Place.of(Relation.RIGHT, null);
            case "in-front":
                return Place.of(Relation.AHEAD, null);
            case "behind-me":
                return Place.of(Relation.BEHIND, null);
            case "near-me":
                return Place.of(Relation.NEAR, null);
            default:
                break;
        }
        Phrase anchor = phrase(c, true);
        if (anchor == null || anchor.world()) {
            throw Refusal.hint(context.hint);
        }
        if (anchor.ground()) {
            return Place.onGround();
        }
        Kind kind = anchor.ref().kind();
        Relation how = switch (relation.lemma()) {
            case "on" -> Relation.ON;
            case "in" -> Relation.IN;
            case "under" -> Relation.UNDER;
            case "from" -> kind == Kind.TABLE ? Relation.ON : kind == Kind.TREE ? Relation.IN : Relation.NEAR;
            default -> Relation.NEAR;
        };
        return Place.of(how, anchor.ref());
    }

    Reference anchorOrRiver(Cursor c) {
        if (c.peekIs(PREP, "of")) {
            c.next();
        }
        Phrase anchor = phrase(c, true);
        if (anchor == null || anchor.ref() == null) {
            return Reference.to(Kind.RIVER); // "the other side" is across the river
        }
        return anchor.ref();
    }

    Reference requiredAnchor(Cursor c) {
        Phrase anchor = phrase(c, true);
        if (anchor == null || anchor.ref() == null) {
            throw Refusal.hint(context.hint);
        }
        return anchor.ref();
    }

    /** The compass place of a direction word at the cursor's left, with its anchor after "of" if any. */
    Place compass(Lexeme direction, Cursor c) {
        Relation relation = Relation.of(sector(direction));
        if (c.peekIs(PREP, "of")) {
            c.next();
            return Place.of(relation, requiredAnchor(c));
        }
        return Place.of(relation, null);
    }

    static Sector sector(Lexeme direction) {
        return Sector.valueOf(direction.lemma().toUpperCase(Locale.ROOT).replace('-', '_'));
    }
}
