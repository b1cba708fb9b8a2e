package io.orchard.server.sim;

import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * An agent in the world: its body, where it stands and walks, and what its controller registered.
 * Mutable, and owned by the simulation's thread.
 */
final class Agent {

    final String name;
    final ClientSession owner;
    final Body body;
    final ModelSpec model;
    /** The secret that gets this agent back after a dropped connection or a restart. */
    final String resumeToken;
    final Set<String> joints = new LinkedHashSet<>();
    final Set<String> timeSensors = new LinkedHashSet<>();
    Vec3 position;
    double heading;
    Motion motion;
    boolean perceptionRequested;
    int perceptionEvery;
    long nextPerceptionTick = -1;

    Agent(String name, ClientSession owner, Body body, ModelSpec model, Vec3 position, double heading,
          String resumeToken) {
        this.name = name;
        this.resumeToken = resumeToken;
        this.owner = owner;
        this.body = body;
        this.model = model;
        this.position = position;
        this.heading = heading;
    }

    /** Everything this agent is, to be handed to another part of the world. */
    AgentHandover handover() {
        return new AgentHandover(name, owner.id(), body, model, position, heading, AgentHandover.Walk.of(motion),
                List.copyOf(joints), List.copyOf(timeSensors), resumeToken, perceptionRequested, perceptionEvery,
                nextPerceptionTick);
    }

    /** The agent handed over, driven by {@code owner}. */
    static Agent of(AgentHandover handed, ClientSession owner) {
        Agent agent = new Agent(handed.name(), owner, handed.body(), handed.model(), handed.position(),
                handed.heading(), handed.resumeToken());
        agent.joints.addAll(handed.joints());
        agent.timeSensors.addAll(handed.timeSensors());
        agent.motion = handed.walk() == null ? null : handed.walk().motion();
        agent.perceptionRequested = handed.perceptionRequested();
        agent.perceptionEvery = handed.perceptionEvery();
        agent.nextPerceptionTick = handed.nextPerceptionTick();
        return agent;
    }

    AgentState state() {
        return new AgentState(name, body, position, heading, model, new ArrayList<>(joints),
                new ArrayList<>(timeSensors));
    }

    /** The agent as a checkpoint keeps it. */
    Checkpoint.SavedAgent saved() {
        return new Checkpoint.SavedAgent(name, body, model, position, heading, List.copyOf(joints),
                List.copyOf(timeSensors), resumeToken);
    }

    /** Whether this agent wants its perception in the tick {@code tick}. */
    boolean perceivesIn(long tick) {
        return perceptionRequested || (perceptionEvery > 0 && tick >= nextPerceptionTick);
    }

    @Override
    public String toString() {
        return name;
    }
}
