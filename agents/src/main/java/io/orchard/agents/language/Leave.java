package io.orchard.agents.language;

import java.util.Objects;

/**
 * Take no fruit that fits, until lifted: "leave the coconuts", "ignore the tomatoes", "don't pick
 * up any coconuts". Neither the agent's own foraging nor an errand collects such fruit; an errand
 * that asks only for it is refused, naming the rule.
 *
 * @param what the fruit to leave alone
 */
public record Leave(Reference what) implements Rule {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Leave {
        Objects.requireNonNull(what, "what");
        if (!what.isFruit()) {
            throw new IllegalArgumentException("only fruit can be left alone, not " + what.kind().wireName());
        }
    }
}
