package io.orchard.cluster;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import java.util.HashSet;
import java.util.Set;

/**
 * A light deterministic agent for games of many agents: it walks straight to the nearest fruit on
 * the ground it sees and grasps it, or on ahead when it sees none. It keeps no map to plan on, so a
 * thousand fit in one test's JVM where a thousand of the paper's agents, each with its maps, do not.
 */
final class Gatherer extends AgentController {

    /** Where it could not walk to. */
    private final Set<Point2> blocked = new HashSet<>();

    Gatherer(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder().build();
    }

    @Override
    protected void decide(Perception seen) {
        if (lastMove() != null && lastMove().rejected()) {
            blocked.add(lastMove().to());
        }
        var fruit = seen.nearestFruit(f -> f.support() == null && !blocked.contains(f.position().onGround()));
        if (fruit.isPresent() && fruit.get().position().onGround().distance(seen.ground()) < 1) {
            face(fruit.get().position().onGround());
            grasp(fruit.get().id());
        } else if (!walking()) {
            walkTo(fruit.isPresent() ? fruit.get().position().onGround()
                    : seen.toWorld(new RelativePosition(10, random().nextDouble() * 2 - 1)));
        }
    }
}
