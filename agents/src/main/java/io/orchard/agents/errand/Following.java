package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.SeenAgent;
import io.orchard.protocol.value.Point2;
import java.util.Comparator;
import java.util.Optional;

/**
 * Following another agent a few steps behind, until it has been out of sight for a while. An
 * agent not in sight when the pursuit starts is looked for.
 */
final class Following implements Pursuit {

    /** How far behind the other it keeps. */
    private static final double BEHIND = 2.5;

    /** How long the other may be out of sight before the agent gives up. */
    private static final double LOST_SECONDS = 15;

    private final Kit kit;
    private final Reference agent;
    private final Looking looking;
    private String name;
    private double lastSeen = Double.NaN;
    private String outcome = "";

    Following(Kit kit, Reference agent) {
        this.kit = kit;
        this.agent = agent;
        this.looking = new Looking(kit, agent);
        this.name = agent.name();
    }

    @Override
    public Status step() {
        Point2 here = kit.here();
        Optional<SeenAgent> seen = kit.memory.agents().stream()
                .filter(a -> name == null || a.name().equalsIgnoreCase(name))
                .min(Comparator.comparingDouble(a -> a.position().distance(here)));
        if (seen.isEmpty()) {
            if (!Double.isNaN(lastSeen) && kit.motor.time() - lastSeen > LOST_SECONDS) {
                outcome = kit.speech.lostSight(name);
                return Status.FAILED;
            }
            if (Double.isNaN(lastSeen)) {
                Status status = looking.step();
                if (status == Status.FAILED) {
                    outcome = looking.failure();
                }
                return status;
            }
            kit.standStill();
            return Status.RUNNING;
        }
        SeenAgent other = seen.get();
        name = other.name();
        lastSeen = kit.motor.time();
        Point2 at = other.position();
        if (here.distance(at) <= BEHIND + other.radius() + kit.memory.radius() + 0.5) {
            kit.standStill();
            return Status.RUNNING;
        }
        if (kit.navigator.goTo(GoingTo.towards(at, here, BEHIND + other.radius()), 1) == Status.FAILED) {
            kit.navigator.reset();
        }
        return Status.RUNNING;
    }

    @Override
    public String outcome() {
        return outcome;
    }
}
