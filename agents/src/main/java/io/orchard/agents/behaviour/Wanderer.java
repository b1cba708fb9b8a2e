package io.orchard.agents.behaviour;

import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.random.RandomGenerator;

/**
 * Walks about at random: picks a free point some way ahead, turned a little to either side,
 * walks there with a {@link Navigator}, and picks the next.
 */
public final class Wanderer {

    private final WorldMemory memory;
    private final RandomGenerator random;
    private Point2 destination;

    /** A wanderer that draws its choices from {@code random}. */
    public Wanderer(WorldMemory memory, RandomGenerator random) {
        this.memory = memory;
        this.random = random;
    }

    /** One tick of wandering with {@code navigator}. */
    public void step(Navigator navigator) {
        for (int attempt = 0; attempt < 4; attempt++) {
            if (destination == null) {
                destination = draw(navigator.planner());
            }
            Status status = navigator.goTo(destination, 1);
            if (status == Status.RUNNING) {
                return;
            }
            destination = null;
            navigator.reset();
        }
    }

    /** Forgets the current destination. */
    public void reset() {
        destination = null;
    }

    private Point2 draw(PathPlanner planner) {
        Point2 here = memory.position();
        for (int attempt = 0; attempt < 12; attempt++) {
            double turn = random.nextGaussian() * (0.5 + attempt * 0.25);
            double distance = 6 + random.nextDouble() * 12;
            Point2 p = Bearings.ahead(here, memory.heading() + turn, distance);
            if (memory.bounds().contains(p.x(), p.z()) && !planner.offLimits(p) && planner.standable(p, 0.2)) {
                return p;
            }
        }
        return Bearings.ahead(here, memory.heading() + Math.PI, 3);
    }
}
