package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Explorer;
import io.orchard.agents.behaviour.Harvester;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.Navigator;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.List;
import java.util.Optional;

/** The behaviours the pursuits of instructed goals share, made once for an agent. */
final class Kit {

    final WorldMemory memory;
    final Motor motor;
    final PathPlanner planner;
    final Navigator navigator;
    final Harvester harvester;
    final Explorer explorer;
    final Grounder grounder;

    Kit(WorldMemory memory, Motor motor, PathPlanner planner) {
        this.memory = memory;
        this.motor = motor;
        this.planner = planner;
        this.navigator = new Navigator(memory, motor, planner);
        this.harvester = new Harvester(memory, motor, navigator);
        this.explorer = new Explorer(memory, planner);
        this.grounder = new Grounder(memory);
    }

    /** Where the agent stands. */
    Point2 here() {
        return motor.position();
    }

    /** Stops walking, if it walks. */
    void standStill() {
        if (motor.walking()) {
            motor.halt();
        }
    }

    /**
     * A free spot next to a thing of radius {@code size} at {@code centre}, on the side facing the
     * agent if that side is free, else around it; empty when there is none known.
     */
    Optional<Point2> besides(Point2 centre, double size) {
        Point2 here = here();
        double distance = size + memory.radius() + 0.6;
        double towards = Math.atan2(here.z() - centre.z(), here.x() - centre.x());
        for (double turn : List.of(0.0, 0.5, -0.5, 1.0, -1.0, 1.6, -1.6, 2.2, -2.2, Math.PI)) {
            Point2 spot = new Point2(centre.x() + distance * Math.cos(towards + turn),
                    centre.z() + distance * Math.sin(towards + turn));
            if (memory.bounds().contains(spot.x(), spot.z()) && !planner.offLimits(spot)
                    && planner.standable(spot, 0.1)) {
                return Optional.of(spot);
            }
        }
        return Optional.empty();
    }
}
