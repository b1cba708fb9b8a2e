package io.orchard.agents.language;

import java.util.Objects;

/**
 * Take only fruit that fits, until lifted: "only bananas from now on", "only collect bananas". A
 * new {@code Only} takes the place of the one before.
 *
 * @param what the only fruit to take
 */
public record Only(Reference what) implements Rule {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Only {
        Objects.requireNonNull(what, "what");
        if (!what.isFruit()) {
            throw new IllegalArgumentException("only fruit can be the only thing to take, not "
                    + what.kind().wireName());
        }
    }
}
