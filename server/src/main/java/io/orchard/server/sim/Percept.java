package io.orchard.server.sim;

import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * What one agent perceived in one tick, kept as the numbers of its messages and the indices of the
 * things it saw in the world's {@link Perceivables}, with no record per thing: a perception is made
 * for every agent on every tick, and a record for each of its thirty or so things (each checking
 * its id, a trip to memory per thing) cost more than finding them. {@link #messages()} makes the
 * three messages of the ordinary form when a client or the record needs them; a writer of the lean
 * form reads the numbers and indices directly.
 *
 * <p>Every number is already rounded as the messages carry it (centimetres and milliradians, as
 * doubles in units and radians), so the messages and any form written from the numbers agree.
 * Immutable once made (the messages are made at most once, by whichever thread asks first, and
 * a perception goes to one client, whose thread alone asks after the simulation's hands it over).
 */
public final class Percept {

    private final Perceivables things;
    private final long tick;
    private final String agent;
    private final Vec3 position;
    private final double heading;
    private final int[] objects;
    /** Per object: distance, bearing. */
    private final double[] objectPlaces;
    private final String[] agents;
    /** Per agent: distance, bearing, heading, radius. */
    private final double[] agentNumbers;
    private final int[] fruit;
    private final PerceivedRiver river;
    private final List<PerceivedBridge> bridges;
    private final Sector castle;
    private List<ServerMessage> messages;

    Percept(Perceivables things, long tick, String agent, Vec3 position, double heading, int[] objects,
            double[] objectPlaces, String[] agents, double[] agentNumbers, int[] fruit, @Nullable PerceivedRiver river,
            List<PerceivedBridge> bridges, Sector castle) {
        this.things = things;
        this.tick = tick;
        this.agent = agent;
        this.position = position;
        this.heading = heading;
        this.objects = objects;
        this.objectPlaces = objectPlaces;
        this.agents = agents;
        this.agentNumbers = agentNumbers;
        this.fruit = fruit;
        this.river = river;
        this.bridges = bridges;
        this.castle = castle;
    }

    /** The world's things, which {@link #objectIndex} and {@link #fruitIndex} index. */
    public Perceivables things() {
        return things;
    }

    /** The tick the perception was computed in. */
    public long tick() {
        return tick;
    }

    /** The perceiving agent's name. */
    public String agent() {
        return agent;
    }

    /** Where the agent stands, rounded to centimetres. */
    public Vec3 position() {
        return position;
    }

    /** The agent's heading, rounded to milliradians. */
    public double heading() {
        return heading;
    }

    /** How many trees and tables the agent sees. */
    public int objectCount() {
        return objects.length;
    }

    /** The index in {@link #things()} of the {@code k}th tree or table seen. */
    public int objectIndex(int k) {
        return objects[k];
    }

    /** The distance to the {@code k}th tree or table seen, rounded to centimetres. */
    public double objectDistance(int k) {
        return objectPlaces[2 * k];
    }

    /** The bearing of the {@code k}th tree or table seen, rounded to milliradians. */
    public double objectBearing(int k) {
        return objectPlaces[2 * k + 1];
    }

    /** How many other agents the agent sees. */
    public int agentCount() {
        return agents.length;
    }

    /** The name of the {@code k}th agent seen. */
    public String agentName(int k) {
        return agents[k];
    }

    /** The distance to the {@code k}th agent seen, rounded to centimetres. */
    public double agentDistance(int k) {
        return agentNumbers[4 * k];
    }

    /** The bearing of the {@code k}th agent seen, rounded to milliradians. */
    public double agentBearing(int k) {
        return agentNumbers[4 * k + 1];
    }

    /** The heading of the {@code k}th agent seen relative to the perceiving agent's, rounded to milliradians. */
    public double agentHeading(int k) {
        return agentNumbers[4 * k + 2];
    }

    /** The radius of the {@code k}th agent seen, as its body has it. */
    public double agentRadius(int k) {
        return agentNumbers[4 * k + 3];
    }

    /** How many fruit the agent sees. */
    public int fruitCount() {
        return fruit.length;
    }

    /** The index in {@link #things()} of the {@code k}th fruit seen. */
    public int fruitIndex(int k) {
        return fruit[k];
    }

    /** The river, when in view. */
    @Nullable
    public PerceivedRiver river() {
        return river;
    }

    /** The bridges in view. */
    public List<PerceivedBridge> bridges() {
        return bridges;
    }

    /** The compass sector the castle lies in. */
    public Sector castle() {
        return castle;
    }

    /**
     * The perception as the ordinary form has it: {@code Perception}, {@code LandmarkPerception} and
     * {@code CastlePerception}.
     */
    public List<ServerMessage> messages() {
        if (messages == null) {
            List<PerceivedObject> seenObjects = new ArrayList<>(objects.length);
            for (int k = 0; k < objects.length; k++) {
                Obstacle o = things.obstacle(objects[k]);
                seenObjects.add(new PerceivedObject(o.id(), o.kind(),
                        new RelativePosition(objectDistance(k), objectBearing(k)), o.radius(), o.height()));
            }
            List<PerceivedAgent> seenAgents = new ArrayList<>(agents.length);
            for (int k = 0; k < agents.length; k++) {
                seenAgents.add(new PerceivedAgent(agents[k], new RelativePosition(agentDistance(k), agentBearing(k)),
                        agentHeading(k), agentRadius(k)));
            }
            List<PerceivedFruit> seenFruit = new ArrayList<>(fruit.length);
            for (int index : fruit) {
                seenFruit.add(things.fruit(index));
            }
            messages = List.of(
                    new PerceptionMessage(tick, agent, position, heading, seenObjects, seenAgents, seenFruit),
                    new LandmarkPerceptionMessage(tick, agent, river, bridges),
                    new CastlePerceptionMessage(tick, agent, castle));
        }
        return messages;
    }
}
