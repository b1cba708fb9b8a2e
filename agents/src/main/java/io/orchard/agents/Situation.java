package io.orchard.agents;

import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Point2;
import java.util.Objects;
import java.util.function.Supplier;

/**
 * What the agent is and knows, as its controller keeps it: the body it declared and the one in
 * force, the server's welcome, its memory of the world, its latest perception, and where it
 * stands and faces. Everything is null until the agent has run that far. Only the declared body
 * may be asked for from any thread; the rest belongs to the controller's thread.
 */
final class Situation {

    private volatile AgentBody plan;
    private WelcomeMessage welcome;
    private Body body;
    private WorldMemory memory;
    private Perception latest;
    private Point2 position;
    private Point2 previousPosition;
    private double heading;

    /** The body the agent declares, asked of it once. Safe from any thread. */
    synchronized AgentBody declared(Supplier<AgentBody> declare) {
        if (plan == null) {
            plan = Objects.requireNonNull(declare.get(), "body() returned null");
        }
        return plan;
    }

    /** The server welcomed the agent. */
    void welcomed(WelcomeMessage welcomed) {
        welcome = welcomed;
    }

    /** The server registered the agent: its body in force, its place, and a memory to fill. */
    void registered(RegisteredMessage registered) {
        body = registered.body();
        position = registered.position().onGround();
        heading = registered.heading();
        memory = new WorldMemory(welcome.bounds(), body.radius(), body.sight());
        memory.placed(position, heading);
    }

    /** A whole perception came: the memory learns from it, and it says where the agent is. */
    void perceived(Perception perception) {
        memory.perceive(perception.message(), perception.landmarks(), perception.castleMessage());
        previousPosition = position;
        position = perception.ground();
        heading = perception.heading();
        latest = perception;
    }

    /** The agent turned to this heading. */
    void turned(double newHeading) {
        heading = newHeading;
    }

    /** Whether the agent is registered, with a memory of the world. */
    boolean inWorld() {
        return memory != null;
    }

    /** Whether the agent stood still between its two latest perceptions. */
    boolean stoodStill() {
        return previousPosition != null && previousPosition.distance(position) < 1e-3;
    }

    AgentBody plan() {
        return plan;
    }

    WelcomeMessage welcome() {
        return welcome;
    }

    Body body() {
        return body;
    }

    WorldMemory memory() {
        return memory;
    }

    Perception latest() {
        return latest;
    }

    Point2 position() {
        return position;
    }

    double heading() {
        return heading;
    }
}
