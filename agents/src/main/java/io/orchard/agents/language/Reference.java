package io.orchard.agents.language;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.ObjectKind;
import java.util.Locale;
import java.util.Objects;

/**
 * What an instruction refers to, as words describe it: "the nearest banana that lies on a table",
 * "the big tree by the river", "Roadrunner", "the other side of the river". A reference is a
 * description, not an object: grounding it means finding, in what the agent remembers of the
 * world, the objects of its {@link #kind()} that fit every other part, and then choosing by
 * {@link #distance()} (or the nearest, when none is given).
 *
 * <p>Each part but the kind is optional and null when the instruction did not say it:
 * <ul>
 *   <li>{@link #kind()}: a fruit kind, any fruit, a tree, a table, the castle, the river, a
 *       bridge, the forest, an agent, or a bare {@linkplain Kind#PLACE place} such as "the
 *       other side of the river", which is nothing but its {@link #place()};</li>
 *   <li>{@link #name()}: the agent's name, for {@link Kind#AGENT} only ("Roadrunner");</li>
 *   <li>{@link #size()}: big or small compared with others of its kind, or the largest or
 *       smallest of those that fit;</li>
 *   <li>{@link #distance()}: the nearest or the farthest of those that fit, measured from the
 *       agent;</li>
 *   <li>{@link #place()}: where it is, relative to another reference (its anchor), such as "on a
 *       table" or "north of the castle".</li>
 * </ul>
 *
 * <p>How many objects an instruction wants is not part of the reference but of the goal that
 * uses it ({@link Collect#count()}).
 *
 * @param kind     what sort of thing it is
 * @param name     the agent's name when {@code kind} is {@link Kind#AGENT} and a name was given
 * @param size     its size, if the instruction said one
 * @param distance nearest or farthest, if the instruction said one
 * @param place    where it is, if the instruction said where
 */
public record Reference(Kind kind, @Nullable String name, @Nullable Size size, @Nullable Distance distance,
                        @Nullable Place place) {

    /**
     * @throws NullPointerException     when {@code kind} is null
     * @throws IllegalArgumentException when a name is given for a kind other than an agent, the name
     *                                  is blank, or a {@link Kind#PLACE} reference has no place
     */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Reference {
        Objects.requireNonNull(kind, "kind");
        if (name != null && kind != Kind.AGENT) {
            throw new IllegalArgumentException("only an agent has a name, but kind is " + kind + " and name '"
                    + name + "'");
        }
        if (name != null && name.isBlank()) {
            throw new IllegalArgumentException("an agent's name must not be blank, was '" + name + "'");
        }
        if (kind == Kind.PLACE && place == null) {
            throw new IllegalArgumentException("a PLACE reference needs a place, such as near the castle");
        }
    }

    /** Any object of this kind: "a tree", "the castle", "fruit". */
    public static Reference to(Kind kind) {
        return new Reference(kind, null, null, null, null);
    }

    /** The agent with this name, such as "Roadrunner". */
    public static Reference agent(String name) {
        return new Reference(Kind.AGENT, Objects.requireNonNull(name, "name"), null, null, null);
    }

    /** A bare place, such as "the other side of the river": {@code Reference.place(Place.beyond(river))}. */
    public static Reference place(Place place) {
        return new Reference(Kind.PLACE, null, null, null, Objects.requireNonNull(place, "place"));
    }

    /** This reference with the given size (null for none). */
    public Reference withSize(@Nullable Size size) {
        return new Reference(kind, name, size, distance, place);
    }

    /** This reference with the given distance (null for none). */
    public Reference withDistance(@Nullable Distance distance) {
        return new Reference(kind, name, size, distance, place);
    }

    /** This reference with the given place (null for none). */
    public Reference withPlace(@Nullable Place place) {
        return new Reference(kind, name, size, distance, place);
    }

    /** Whether this refers to fruit: any fruit, or tomatoes, bananas or coconuts. */
    public boolean isFruit() {
        return kind.isFruit();
    }

    /**
     * One object of this reference in words, with its article, as the agent says it: "a coconut
     * that lies on a table", "the nearest tree", "Roadrunner".
     */
    public String words() {
        return Restatement.noun(this);
    }

    /** This reference in the compact notation of {@link Goal#notation()}, e.g. {@code nearest banana on(table)}. */
    public String notation() {
        return Notation.of(this);
    }

    /** The sorts of thing an instruction can refer to. */
    public enum Kind {
        /** Any fruit: "fruit", "everything", "something". */
        FRUIT(null, null),
        /** A tomato. */
        TOMATO(FruitKind.TOMATO, null),
        /** A banana. */
        BANANA(FruitKind.BANANA, null),
        /** A coconut. */
        COCONUT(FruitKind.COCONUT, null),
        /** A tree of the forest; fruit may hang in it or lie under it. */
        TREE(null, ObjectKind.TREE),
        /** A table; fruit may lie on it. */
        TABLE(null, ObjectKind.TABLE),
        /** The castle; agents perceive only the compass sector it lies in. */
        CASTLE(null, null),
        /** The river, which divides the world; it is crossed by a bridge. */
        RIVER(null, null),
        /** One of the two bridges across the river. */
        BRIDGE(null, null),
        /** The forest: the area where the trees stand. */
        FOREST(null, null),
        /** Where the agent started the game: "go back to where you started". */
        START(null, null),
        /** An agent, by {@link Reference#name()} or, without a name, any agent. */
        AGENT(null, null),
        /** No object, only the area its {@link Reference#place()} describes ("north of the castle"). */
        PLACE(null, null);

        private final FruitKind fruitKind;
        private final ObjectKind objectKind;

        Kind(FruitKind fruitKind, ObjectKind objectKind) {
            this.fruitKind = fruitKind;
            this.objectKind = objectKind;
        }

        /** The name of this kind in JSON and in the notation: {@code tomato}, {@code tree}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** Whether this is any fruit or one kind of fruit. */
        public boolean isFruit() {
            return this == FRUIT || fruitKind != null;
        }

        /** The protocol's kind of fruit for tomatoes, bananas and coconuts; null for any other kind, FRUIT included. */
        public @Nullable FruitKind fruitKind() {
            return fruitKind;
        }

        /** Whether a fruit of this protocol kind is one this kind refers to: FRUIT matches every kind. */
        public boolean matches(FruitKind kind) {
            return this == FRUIT || fruitKind == kind;
        }

        /** The perceived kind of object for trees and tables; null for every other kind. */
        public @Nullable ObjectKind objectKind() {
            return objectKind;
        }

        /** The kind whose {@link #wireName()} is this, or null. */
        static @Nullable Kind ofWireName(String wireName) {
            for (Kind kind : values()) {
                if (kind.wireName().equals(wireName)) {
                    return kind;
                }
            }
            return null;
        }
    }

    /**
     * A size said in words. Fruit of one kind all have about the same size, so sizes matter most
     * for trees and tables (their bounding cylinders differ).
     */
    public enum Size {
        /** Bigger than most of its kind: "big", "large", "tall", "huge". */
        BIG,
        /** Smaller than most of its kind: "small", "little", "tiny", "short". */
        SMALL,
        /** The biggest of those that fit the rest of the reference: "largest", "biggest", "tallest". */
        LARGEST,
        /** The smallest of those that fit the rest of the reference: "smallest", "tiniest". */
        SMALLEST;

        /** The name of this size in JSON and in the notation: {@code big}, {@code largest}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * Which one of the objects that fit to choose: by their distance from the agent, their height
     * (fruit), or how far they lie in a compass direction ("the northern bridge").
     */
    public enum Distance {
        /** The closest to the agent: "nearest", "closest". */
        NEAREST,
        /** The farthest from the agent: "farthest", "furthest". */
        FARTHEST,
        /** The highest above the ground: "the highest coconut". */
        HIGHEST,
        /** The lowest: "the lowest banana". */
        LOWEST,
        /** The farthest to the north: "the northern bridge", "the northernmost tree". */
        NORTHERNMOST,
        /** The farthest to the south: "the southern bridge". */
        SOUTHERNMOST,
        /** The farthest to the east: "the eastern table". */
        EASTERNMOST,
        /** The farthest to the west: "the westernmost tree". */
        WESTERNMOST;

        /** The name of this choice in JSON and in the notation: {@code nearest}, {@code northernmost}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }
}
