package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Sector;
import java.util.Locale;
import java.util.Objects;

/**
 * Where a referred object is, relative to an anchor that is itself a {@link Reference}: "on a
 * table", "under the tree", "by the river", "on the other side of the river", "north of the
 * castle". Places nest through their anchors: "the banana on the table near the castle" is a
 * banana {@code on} a table that is {@code near} the castle.
 *
 * @param relation how the object stands to the anchor
 * @param anchor   what it stands in relation to; null for {@link Relation#ON_GROUND}, for the
 *                 relations from the agent's heading ({@link Relation#LEFT}, ...), and for
 *                 {@link Relation#NEAR} or a compass relation said without an anchor ("near you", "the
 *                 tree to the north"), which are then taken from where the agent stood when told
 */
public record Place(Relation relation, @Nullable Reference anchor) {

    /**
     * @throws NullPointerException     when {@code relation} is null
     * @throws IllegalArgumentException when the relation needs an anchor and has none, or is
     *                                  {@link Relation#ON_GROUND} and has one
     */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Place {
        Objects.requireNonNull(relation, "relation");
        if (relation == Relation.ON_GROUND && anchor != null) {
            throw new IllegalArgumentException("ON_GROUND takes no anchor, was given " + anchor);
        }
        if (anchor == null && relation != Relation.ON_GROUND && relation.sector() == null
                && relation != Relation.NEAR && !relation.fromHeading()) {
            throw new IllegalArgumentException(relation + " needs an anchor, such as a table or the river");
        }
        if (relation == Relation.FOUND && anchor != null && !anchor.isFruit()) {
            throw new IllegalArgumentException("FOUND takes a fruit as its anchor, was given " + anchor);
        }
        if (anchor != null && relation.fromHeading()) {
            throw new IllegalArgumentException(relation + " is taken from the agent's heading and takes no anchor, "
                    + "was given " + anchor);
        }
    }

    /** A place in this relation to an anchor. */
    public static Place of(Relation relation, @Nullable Reference anchor) {
        return new Place(relation, anchor);
    }

    /** On the ground, neither on a table nor in a tree. */
    public static Place onGround() {
        return new Place(Relation.ON_GROUND, null);
    }

    /** How an object stands to the anchor of its place. */
    public enum Relation {
        /** Lying on the anchor, a table: "on the table", "from the table". */
        ON,
        /** Inside the anchor: hanging in a tree, or within the forest. */
        IN,
        /** On the ground beneath the anchor, a tree's crown: "under the tree". */
        UNDER,
        /** On the ground, not on a table nor in a tree. Takes no anchor. */
        ON_GROUND,
        /** Close to the anchor: "near", "by", "next to", "beside", "at". */
        NEAR,
        /**
         * On the far side of the anchor, seen from the agent: "across the bridge", "on the other side
         * of the river", "beyond the river", "behind the castle".
         */
        BEYOND,
        /** On the same side of the anchor as the agent: "on this side of the river". */
        THIS_SIDE_OF,
        /** North of the anchor (or of the agent, without an anchor). */
        NORTH_OF,
        /** North-east of the anchor (or of the agent). */
        NORTH_EAST_OF,
        /** East of the anchor (or of the agent). */
        EAST_OF,
        /** South-east of the anchor (or of the agent). */
        SOUTH_EAST_OF,
        /** South of the anchor (or of the agent). */
        SOUTH_OF,
        /** South-west of the anchor (or of the agent). */
        SOUTH_WEST_OF,
        /** West of the anchor (or of the agent). */
        WEST_OF,
        /** North-west of the anchor (or of the agent). */
        NORTH_WEST_OF,
        /** On the agent's left, from its heading when told: "on your left". Takes no anchor. */
        LEFT,
        /** On the agent's right: "on your right", "to your right". Takes no anchor. */
        RIGHT,
        /** In front of the agent: "in front of you", "ahead of you". Takes no anchor. */
        AHEAD,
        /** Behind the agent: "behind you". Takes no anchor. */
        BEHIND,
        /** The one of those that fit that is nearest to the anchor: "the fruit closest to the bridge". */
        CLOSEST_TO,
        /** The one of those that fit that is farthest from the anchor: "the table farthest from the castle". */
        FARTHEST_FROM,
        /**
         * Where the agent found the anchor, a fruit it has picked up: "where you found the coconut" is the
         * spot it stood on when it took the last coconut it took.
         */
        FOUND;

        /** Whether this relation is taken from the agent's heading: left, right, ahead, behind. */
        public boolean fromHeading() {
            return this == LEFT || this == RIGHT || this == AHEAD || this == BEHIND;
        }

        /** The name of this relation in JSON and in the notation: {@code on}, {@code north-east-of}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }

        /** The compass sector of a compass relation ({@code NORTH_OF} gives {@code NORTH}); null for the others. */
        public @Nullable Sector sector() {
            return switch (this) {
                case NORTH_OF -> Sector.NORTH;
                case NORTH_EAST_OF -> Sector.NORTH_EAST;
                case EAST_OF -> Sector.EAST;
                case SOUTH_EAST_OF -> Sector.SOUTH_EAST;
                case SOUTH_OF -> Sector.SOUTH;
                case SOUTH_WEST_OF -> Sector.SOUTH_WEST;
                case WEST_OF -> Sector.WEST;
                case NORTH_WEST_OF -> Sector.NORTH_WEST;
                default -> null;
            };
        }

        /** The compass relation of a sector: {@code NORTH} gives {@code NORTH_OF}. */
        public static Relation of(Sector sector) {
            return valueOf(Objects.requireNonNull(sector, "sector").name() + "_OF");
        }
    }
}
