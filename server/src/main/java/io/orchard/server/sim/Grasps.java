package io.orchard.server.sim;

import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.Fruit;
import io.orchard.server.world.ReachResult;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Decides the grasps of a tick. All grasps of a tick are weighed together, so that when two agents
 * reach for the same fruit exactly one gets it, by a rule that does not depend on timing: the agent
 * whose body centre is nearest to the fruit wins; on a tie, the one whose request was applied first
 * (client by client in the order of their agents' names).
 */
final class Grasps {

    /** A grasp asked for in this tick. */
    record Request(Agent agent, GraspRequestMessage message) {}

    private final World world;
    /** The agents in the world, by name. */
    private final Map<String, Agent> agents;
    private final Scoreboard scores;
    private final Outbox outbox;
    private final List<GameListener> listeners;
    private final Map<String, List<Request>> byFruit = new LinkedHashMap<>();
    /** The same requests in the order they were asked for. */
    private final List<Request> asked = new ArrayList<>();

    Grasps(World world, Map<String, Agent> agents, Scoreboard scores, Outbox outbox, List<GameListener> listeners) {
        this.world = world;
        this.agents = agents;
        this.scores = scores;
        this.outbox = outbox;
        this.listeners = listeners;
    }

    void request(Agent agent, GraspRequestMessage message, boolean running) {
        if (!running) {
            fail(agent, message, "the game is not running");
            return;
        }
        Request request = new Request(agent, message);
        byFruit.computeIfAbsent(message.fruit(), f -> new ArrayList<>()).add(request);
        asked.add(request);
    }

    /**
     * The grasps asked for so far in this tick, in the order they were asked for, and forgets them:
     * for a part of a world whose agents may grasp fruit that another part decides on.
     */
    List<Request> take() {
        List<Request> all = new ArrayList<>(asked);
        clear();
        return all;
    }

    void clear() {
        byFruit.clear();
        asked.clear();
    }

    /** Decides the grasps asked for in this tick; true when a fruit was collected, so that scores changed. */
    boolean resolve(long tick, double time) {
        boolean collected = false;
        for (Map.Entry<String, List<Request>> entry : byFruit.entrySet()) {
            Fruit fruit = world.fruit(entry.getKey()).orElse(null);
            Request winner = null;
            double best = Double.MAX_VALUE;
            List<Request> reachable = new ArrayList<>();
            for (Request request : entry.getValue()) {
                if (!agents.containsKey(request.agent().name)) {
                    continue; // it left during the tick
                }
                if (fruit == null) {
                    fail(request.agent(), request.message(), "fruit " + entry.getKey() + " is not in the world");
                    continue;
                }
                Agent agent = request.agent();
                ReachResult reach = world.reach(agent.position, agent.heading, agent.body, fruit);
                if (!reach.reachable()) {
                    fail(agent, request.message(), reach.reason());
                    continue;
                }
                reachable.add(request);
                double distance = agent.position.groundDistance(fruit.position());
                if (distance < best) {
                    best = distance;
                    winner = request;
                }
            }
            if (winner == null) {
                continue;
            }
            for (Request request : reachable) {
                if (request != winner) {
                    fail(request.agent(), request.message(), "fruit " + fruit.id() + " was taken by " + winner.agent().name);
                }
            }
            collect(winner, fruit, tick, time);
            collected = true;
        }
        clear();
        return collected;
    }

    private void collect(Request winner, Fruit fruit, long tick, double time) {
        Agent agent = winner.agent();
        world.removeFruit(fruit.id());
        int points = scores.collect(agent.name, fruit.kind());
        outbox.send(agent.owner, new GraspResultMessage(winner.message().seq(), agent.name, fruit.id(), true, null,
                points));
        outbox.broadcast(new FruitEatenMessage(tick, fruit.id(), fruit.kind(), agent.name), Audience.AGENTS);
        outbox.broadcast(new FruitRemovedMessage(tick, fruit.id(), agent.name), Audience.VIEWERS);
        listeners.forEach(l -> l.fruitEaten(agent.name, fruit.id(), fruit.kind(), time));
    }

    private void fail(Agent agent, GraspRequestMessage message, String reason) {
        outbox.send(agent.owner, new GraspResultMessage(message.seq(), agent.name, message.fruit(), false, reason, 0));
    }
}
