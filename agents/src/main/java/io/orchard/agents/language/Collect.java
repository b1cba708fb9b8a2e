package io.orchard.agents.language;

import java.util.Objects;

/**
 * Collect fruit: "pick up the banana", "grab the coconut on the table", "eat the tomato under the
 * tree", "collect three bananas", "get the nearest fruit", "collect everything on the other side
 * of the river". The agent finds fruit that fits {@link #what()} (exploring when it knows of none),
 * walks to it and grasps it, until it has collected {@link #count()} of them or, for
 * {@link #ALL}, until it knows of no more.
 *
 * @param what  the fruit to collect; its kind is a fruit kind or any fruit
 * @param count how many: at least 1, or {@link #ALL}
 */
public record Collect(Reference what, int count) implements Goal {

    /** The count of "all", "every", "everything" and bare plurals ("collect bananas"). */
    public static final int ALL = Integer.MAX_VALUE;

    /** @throws IllegalArgumentException when {@code what} is not fruit or {@code count} is less than 1 */
    /** Checks the components; a bad value is refused with an exception that names it. */
    public Collect {
        Objects.requireNonNull(what, "what");
        if (!what.isFruit()) {
            throw new IllegalArgumentException("only fruit can be collected, not " + what.kind());
        }
        if (count < 1) {
            throw new IllegalArgumentException("count must be at least 1 (or ALL), was " + count);
        }
    }

    /** One fruit that fits {@code what}. */
    public static Collect one(Reference what) {
        return new Collect(what, 1);
    }

    /** Every fruit that fits {@code what}. */
    public static Collect all(Reference what) {
        return new Collect(what, ALL);
    }

    /** Whether this collects every fruit that fits rather than a number of them. */
    public boolean isAll() {
        return count == ALL;
    }
}
