package io.orchard.agents.map;

import io.orchard.protocol.value.Nullable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What a rejected move ran into, read from the reason the server gave ("path crosses tree T17",
 * "path enters the castle", "path enters the river outside a bridge", "path leaves the world").
 * Rejections for other reasons (a stale {@code from}, a game not running) are {@link #NONE}.
 */
public enum Obstruction {
    /** A tree's trunk; the reason names the tree. */
    TREE,
    /** A table; the reason names the table. */
    TABLE,
    /** The castle's walls. */
    CASTLE,
    /** The river away from the bridges. */
    RIVER,
    /** The edge of the world. */
    EDGE,
    /** Not an obstruction at all. */
    NONE;

    private static final Pattern NAMED = Pattern.compile("(?:crosses|overlaps) (tree|table) (\\S+)");

    /** What the reason names; {@link #NONE} for a null reason or one about something else. */
    public static Obstruction of(@Nullable String reason) {
        if (reason == null) {
            return NONE;
        }
        Matcher named = NAMED.matcher(reason);
        if (named.find()) {
            return named.group(1).equals("tree") ? TREE : TABLE;
        }
        if (reason.contains("castle")) {
            return CASTLE;
        }
        if (reason.contains("river")) {
            return RIVER;
        }
        if (reason.contains("leaves the world") || reason.contains("outside the world")) {
            return EDGE;
        }
        return NONE;
    }

    /** The id of the tree or table the reason names, or null. */
    public static @Nullable String objectId(@Nullable String reason) {
        if (reason == null) {
            return null;
        }
        Matcher named = NAMED.matcher(reason);
        return named.find() ? named.group(2) : null;
    }

    /** Whether this is something in the world that blocks walking (everything but {@link #NONE}). */
    public boolean isObstacle() {
        return this != NONE;
    }
}
