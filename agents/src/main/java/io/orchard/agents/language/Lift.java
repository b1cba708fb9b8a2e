package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;

/**
 * Lift rules: "you can go near the river again" lifts the rules about the area near the river,
 * "you may take coconuts again" those that keep the agent from coconuts, "forget the rules" all of
 * them. Lifting a rule no one set is answered as such.
 *
 * @param what what the rules to lift are about (an area or fruit); null for every rule
 */
public record Lift(@Nullable Reference what) implements Goal {

    /** Lift every rule. */
    public static Lift all() {
        return new Lift(null);
    }
}
