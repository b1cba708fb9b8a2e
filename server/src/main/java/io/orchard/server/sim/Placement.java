package io.orchard.server.sim;

import io.orchard.protocol.value.Vec3;

/**
 * Where a newly registered agent stands. The default draws free places from the game's seeded
 * generator; experiments and tests can put agents where they want them.
 */
@FunctionalInterface
public interface Placement {

    /**
     * A place for the agent {@code name} of body radius {@code radius}, or null to let the default
     * draw one. The simulation checks that the place is free of obstacles and agents.
     */
    Vec3 placeFor(String name, double radius);
}
