package org.example.orchardconsumer;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.protocol.value.RelativePosition;

/** This program's own agent: it walks to the nearest fruit lying on the ground and grasps it. */
final class Gatherer extends AgentController {

    Gatherer() {
        super("Gatherer");
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder().build();
    }

    @Override
    protected void decide(Perception seen) {
        var fruit = seen.nearestFruit(f -> f.support() == null);
        if (fruit.isPresent() && fruit.get().position().onGround().distance(seen.ground()) < 1) {
            face(fruit.get().position().onGround());
            grasp(fruit.get().id());
        } else if (!walking()) { // to the fruit, or somewhere ahead when none is in view
            walkTo(fruit.isPresent() ? fruit.get().position().onGround()
                    : seen.toWorld(new RelativePosition(10, random().nextDouble() * 2 - 1)));
        }
    }
}
