package io.orchard.server.world;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;

/**
 * The answer to "may an agent move along this segment?" (or "may it stand here?"): free, or blocked
 * by the first thing the agent would meet, named in words an agent's author can act on ("path
 * crosses tree T17").
 *
 * @param obstruction what blocks the way; {@link Obstruction#NONE} when the way is free
 * @param objectId    the id of the tree or table in the way; null for the others
 * @param travel      the fraction of the path the agent can travel before it touches what blocks
 *                    it, in [0, 1]; 1 when free. Exact for trees, tables and the world's edge; for
 *                    the castle and the river it is rounded down to 1/1024 of the path
 * @param reason      the answer in words: "path is free", "path crosses tree T17"...
 */
public record MoveResult(Obstruction obstruction, @Nullable String objectId, double travel, String reason) {

    private static final MoveResult FREE = new MoveResult(Obstruction.NONE, null, 1, "path is free");
    private static final MoveResult PLACE_FREE = new MoveResult(Obstruction.NONE, null, 1, "position is free");

    /** What can block an agent. */
    public enum Obstruction {
        /** Nothing: the way is free. */
        NONE,
        /** The edge of the world. */
        EDGE,
        /** A tree's trunk. */
        TREE,
        /** A table. */
        TABLE,
        /** The castle's walls. */
        CASTLE,
        /** The river, away from the bridges. */
        RIVER
    }

    /** Checks the components; a bad value is refused with an exception that names it. */
    public MoveResult {
        Checks.present(obstruction, "obstruction");
        Checks.finite(travel, "travel");
        Checks.present(reason, "reason");
        if (travel < 0 || travel > 1) {
            throw new IllegalArgumentException("travel must be between 0 and 1, was " + travel);
        }
    }

    static MoveResult free(boolean standing) {
        return standing ? PLACE_FREE : FREE;
    }

    /** Whether the agent may make the move (or stand there). */
    public boolean isFree() {
        return obstruction == Obstruction.NONE;
    }
}
