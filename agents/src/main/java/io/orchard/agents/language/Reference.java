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
 * uses it ({@link Collect#count()}). Two parts pick one object more narrowly still:
 * <ul>
 *   <li>{@link #ordinal()}: which one, counted in the order of {@link #distance()}: "the second
 *       table from the left" is the 2nd {@link Distance#LEFTMOST}, "the third tree" the 3rd
 *       {@link Distance#NEAREST};</li>
 *   <li>{@link #id()}: the very object, by the world's id ("T3"): a demonstrative ("that table")
 *       resolved from what the agent last spoke about, or what a condition's "it" stands for.</li>
 * </ul>
 *
 * @param kind     what sort of thing it is
 * @param name     the agent's name when {@code kind} is {@link Kind#AGENT} and a name was given
 * @param size     its size, if the instruction said one
 * @param distance which one to choose, or the order to count in, if the instruction said one
 * @param place    where it is, if the instruction said where
 * @param ordinal  the place in the order of {@code distance}, 2 or more (the first is the one
 *                 {@code distance} picks: 1 is kept as null); null when none was said
 * @param id       the world's id of the one object meant; null for a description
 */
public record Reference(Kind kind, @Nullable String name, @Nullable Size size, @Nullable Distance distance,
                        @Nullable Place place, @Nullable Integer ordinal, @Nullable String id) {

    /** The largest ordinal understood: "the twentieth tree". */
    public static final int MAX_ORDINAL = 20;

    /**
     * Checks the components; a bad value is refused with an exception that names it: a name for a kind other
     * than an agent, a blank name, a {@link Kind#PLACE} reference without a place, an ordinal without an order
     * or out of range, an id for a kind without ids.
     */
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
        if (ordinal != null && ordinal == 1) {
            ordinal = null; // the first is the one the distance picks
        }
        if (ordinal != null && (ordinal < 1 || ordinal > MAX_ORDINAL)) {
            throw new IllegalArgumentException("an ordinal must be 1 to " + MAX_ORDINAL + ", was " + ordinal);
        }
        if (ordinal != null && distance == null) {
            throw new IllegalArgumentException("an ordinal counts in an order, such as nearest or leftmost; "
                    + "the distance is missing for ordinal " + ordinal);
        }
        if (id != null && (id.isBlank() || !kind.hasIds())) {
            throw new IllegalArgumentException("an id names one fruit, tree, table or bridge, not a " + kind.wireName()
                    + "; was '" + id + "'");
        }
    }

    /** A reference without an ordinal or an id. */
    public Reference(Kind kind, @Nullable String name, @Nullable Size size, @Nullable Distance distance,
                     @Nullable Place place) {
        this(kind, name, size, distance, place, null, null);
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

    /** The one object of this kind with this world's id: "the table T3". */
    public static Reference thing(Kind kind, String id) {
        return new Reference(kind, null, null, null, null, null, Objects.requireNonNull(id, "id"));
    }

    /** This reference with the given size (null for none). */
    public Reference withSize(@Nullable Size size) {
        return new Reference(kind, name, size, distance, place, ordinal, id);
    }

    /** This reference with the given distance (null for none); an ordinal goes with the distance it counted in. */
    public Reference withDistance(@Nullable Distance distance) {
        return new Reference(kind, name, size, distance, place, distance == null ? null : ordinal, id);
    }

    /** This reference with the given place (null for none). */
    public Reference withPlace(@Nullable Place place) {
        return new Reference(kind, name, size, distance, place, ordinal, id);
    }

    /** This reference counting in the order of {@code distance} to the {@code ordinal}-th: "the second from the left". */
    public Reference withOrdinal(int ordinal, Distance distance) {
        return new Reference(kind, name, size, Objects.requireNonNull(distance, "distance"), place, ordinal, id);
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

        /** Whether the world gives objects of this kind ids: fruit ("F12"), trees, tables and bridges. */
        public boolean hasIds() {
            return isFruit() || this == TREE || this == TABLE || this == BRIDGE;
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
        WESTERNMOST,
        /**
         * The farthest to the left, as the agent stood and faced when told: "the leftmost table",
         * counted "from the left". Only what lies ahead of the agent is counted, when anything fits there.
         */
        LEFTMOST,
        /** The farthest to the right, as the agent faced when told: "the second tree from the right". */
        RIGHTMOST;

        /** The name of this choice in JSON and in the notation: {@code nearest}, {@code northernmost}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }
}
