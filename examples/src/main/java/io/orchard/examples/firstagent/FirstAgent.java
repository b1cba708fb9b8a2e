package io.orchard.examples.firstagent;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import java.util.HashSet;
import java.util.Set;

/** A first agent: it walks to the nearest fruit it sees lying on the ground, and grasps it. */
public class FirstAgent extends AgentController {

    private final Set<Point2> blocked = new HashSet<>(); // where it could not walk to

    public FirstAgent(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder().build(); // radius 0.5, speed 5, hands that reach 0.6 beyond it
    }

    @Override
    protected void decide(Perception seen) {
        if (lastMove() != null && lastMove().rejected()) {
            blocked.add(lastMove().to()); // a tree, the castle, the river or the edge is in the way
        }
        var fruit = seen.nearestFruit(f -> f.support() == null && !blocked.contains(f.position().onGround()));
        if (fruit.isPresent() && fruit.get().position().onGround().distance(seen.ground()) < 1) {
            face(fruit.get().position().onGround());
            grasp(fruit.get().id());
        } else if (!walking()) { // to the fruit, or 10 units ahead, give or take a turn, when none is in view
            walkTo(fruit.isPresent() ? fruit.get().position().onGround()
                    : seen.toWorld(new RelativePosition(10, random().nextDouble() * 2 - 1)));
        }
    }
}
