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
     * draw one. The simulation checks that the place is free of obstacles, and of agents: of those
     * already in the world for an agent that joins a running game; before the start, of those whose
     * names sort first, once the game starts (so that the order in which agents came does not show).
     */
    Vec3 placeFor(String name, double radius);
}
