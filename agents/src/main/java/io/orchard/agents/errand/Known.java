package io.orchard.agents.errand;

import io.orchard.agents.language.Reference;
import io.orchard.agents.map.KnownBridge;
import io.orchard.agents.map.KnownFruit;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;

/**
 * One object of the world as the agent remembers it, seen through the words of a reference: what
 * a reference was grounded to.
 *
 * @param kind   what sort of thing it is
 * @param id     the world's id ({@code F12}, {@code T3}, {@code B1}), or the agent's name; the kind's
 *               name for the castle, the river and the forest, which have none
 * @param where  where it is on the ground: its centre, or the nearest known point of the river
 * @param size   its radius: a fruit's, a crown's, a table top's; half a bridge's length
 * @param fruit  the fruit, when it is one
 * @param bridge the bridge, when it is one
 */
record Known(Reference.Kind kind, String id, Point2 where, double size, @Nullable KnownFruit fruit,
             @Nullable KnownBridge bridge) {

    /** A thing that is neither a fruit nor a bridge. */
    static Known of(Reference.Kind kind, String id, Point2 where, double size) {
        return new Known(kind, id, where, size, null, null);
    }

    /** A fruit the agent knows of. */
    static Known fruit(KnownFruit fruit) {
        return new Known(Reference.Kind.valueOf(fruit.kind().name()), fruit.id(), fruit.ground(), fruit.radius(), fruit,
                null);
    }

    /** The agent itself, standing at a point: for asking whether it has reached a place. */
    static Known standing(Point2 where) {
        return of(Reference.Kind.AGENT, "me", where, 0);
    }
}
