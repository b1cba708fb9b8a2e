package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.Vec3;

import java.util.List;

/**
 * What the agent perceives (the paper's PerceptionMessage): trees, tables and other agents by
 * relative position, fruit by absolute position. Perception is limited in range, in direction (the
 * field of view around the heading) and in area (nothing is seen through the castle).
 *
 * @param tick the tick it was computed in
 * @param agent the perceiving agent
 * @param position the agent's own position
 * @param heading the agent's own heading in radians
 * @param objects trees and tables in view
 * @param agents other agents in view
 * @param fruit fruit in view
 */
public record PerceptionMessage(long tick,
                                String agent,
                                Vec3 position,
                                double heading,
                                List<PerceivedObject> objects,
                                List<PerceivedAgent> agents,
                                List<PerceivedFruit> fruit) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceptionMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.present(position, "position");
        Checks.finite(heading, "heading");
        objects = Checks.list(objects, "objects");
        agents = Checks.list(agents, "agents");
        fruit = Checks.list(fruit, "fruit");
    }
}
