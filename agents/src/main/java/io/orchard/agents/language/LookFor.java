package io.orchard.agents.language;

import java.util.Objects;

/**
 * Search for something until it is in sight, without collecting it: "look for coconuts", "find the
 * castle", "search the forest for bananas". The goal is reached when the agent perceives an object
 * that fits {@link #what()}; the agent then stops and reports it.
 *
 * @param what what to search for
 */
public record LookFor(Reference what) implements Goal {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LookFor {
        Objects.requireNonNull(what, "what");
    }
}
