package io.orchard.agents;

import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.Point2;
import java.util.Optional;

/** The example agent of the package documentation, as a student would write it. */
public final class Pippin extends AgentController {

    public Pippin() {
        super("Pippin");
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder().radius(0.4).speed(6).gripper("hands", 0.6, 0, 1.6).build();
    }

    @Override
    protected void decide(Perception seen) {
        if (pursueInstruction()) {               // told what to do: that comes first
            return;
        }
        Point2 here = seen.ground();
        Gripper hands = bodyInForce().gripper();
        Optional<PerceivedFruit> fruit = seen.nearestFruit(f -> f.position().y() < hands.maxHeight() - 0.01);
        if (fruit.isEmpty()) {                    // nothing in view: walk on, somewhere new
            if (!walking()) {
                walkTo(Bearings.ahead(here, heading() + random().nextGaussian(), 10));
            }
            return;
        }
        Point2 at = fruit.get().position().onGround();
        double reach = bodyInForce().radius() + hands.reach() + fruit.get().radius();
        if (here.distance(at) < reach - 0.1) {   // within reach: face it and grasp
            face(at);
            grasp(fruit.get().id());
        } else if (!walking()) {          // walk up to it
            walkTo(Bearings.ahead(here, Bearings.headingTowards(here, at), here.distance(at) - reach + 0.3));
        }
    }
}
