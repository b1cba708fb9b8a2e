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

    private record Request(Agent agent, GraspRequestMessage message) {}

    private final Simulation sim;
    private final World world;
    private final Map<String, List<Request>> byFruit = new LinkedHashMap<>();

    Grasps(Simulation sim, World world) {
        this.sim = sim;
        this.world = world;
    }

    void request(Agent agent, GraspRequestMessage message, boolean running) {
        if (!running) {
            fail(agent, message, "the game is not running");
            return;
        }
        byFruit.computeIfAbsent(message.fruit(), f -> new ArrayList<>()).add(new Request(agent, message));
    }

    void clear() {
        byFruit.clear();
    }

    void resolve(long tick, double time) {
        for (Map.Entry<String, List<Request>> entry : byFruit.entrySet()) {
            Fruit fruit = world.fruit(entry.getKey()).orElse(null);
            Request winner = null;
            double best = Double.MAX_VALUE;
            List<Request> reachable = new ArrayList<>();
            for (Request request : entry.getValue()) {
                if (!sim.agents.containsKey(request.agent().name)) {
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
        }
        byFruit.clear();
    }

    private void collect(Request winner, Fruit fruit, long tick, double time) {
        Agent agent = winner.agent();
        world.removeFruit(fruit.id());
        int points = sim.scores.collect(agent.name, fruit.kind());
        sim.send(agent.owner, new GraspResultMessage(winner.message().seq(), agent.name, fruit.id(), true, null, points));
        sim.broadcast(new FruitEatenMessage(tick, fruit.id(), fruit.kind(), agent.name), Audience.AGENTS);
        sim.broadcast(new FruitRemovedMessage(tick, fruit.id(), agent.name), Audience.VIEWERS);
        sim.scoreChanged();
        sim.fruitEaten(agent, fruit);
    }

    private void fail(Agent agent, GraspRequestMessage message, String reason) {
        sim.send(agent.owner, new GraspResultMessage(message.seq(), agent.name, message.fruit(), false, reason, 0));
    }
}
