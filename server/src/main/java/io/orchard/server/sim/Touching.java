package io.orchard.server.sim;

import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The sets of agents whose walks in one tick depend on each other's. Walking moves agents one after
 * the other in the order of their names, each stopping where it would touch one already moved; an
 * agent's tick therefore depends on the agents it could touch, where they stand or where they walk
 * to, and on theirs in turn, and on no other. Two agents could touch when one of the places of one
 * (where it stands, where it walks to in the tick) lies closer to one of the other's than their radii
 * together.
 */
final class Touching {

    private Touching() {}

    /**
     * The sets, each in the order of the names, of {@code agents} (given in the order of their names)
     * as they walk to simulated {@code time}; no agent walks more than {@code step} in a tick nor is
     * wider than {@code maxRadius}.
     */
    static List<List<Agent>> sets(List<Agent> agents, double time, double maxRadius, double step) {
        int n = agents.size();
        Vec3[] next = new Vec3[n];
        Map<Agent, Integer> index = new IdentityHashMap<>();
        for (int i = 0; i < n; i++) {
            Agent agent = agents.get(i);
            next[i] = agent.motion == null ? agent.position : agent.motion.positionAt(time);
            index.put(agent, i);
        }
        int[] parent = new int[n];
        for (int i = 0; i < n; i++) {
            parent[i] = i;
        }
        double reach = 2 * maxRadius + 2 * step + 1e-6;
        AgentGrid grid = new AgentGrid(agents, Math.max(1, reach));
        for (int i = 0; i < n; i++) {
            Agent a = agents.get(i);
            int self = i;
            grid.forEachWithin(a.position, reach, b -> {
                int j = index.get(b);
                if (j > self && couldTouch(a, next[self], b, next[j])) {
                    parent[find(parent, self)] = find(parent, j);
                }
            });
        }
        Map<Integer, List<Agent>> sets = new LinkedHashMap<>();
        for (int i = 0; i < n; i++) {
            sets.computeIfAbsent(find(parent, i), root -> new ArrayList<>()).add(agents.get(i));
        }
        return new ArrayList<>(sets.values());
    }

    private static boolean couldTouch(Agent a, Vec3 aNext, Agent b, Vec3 bNext) {
        double reach = a.body.radius() + b.body.radius();
        return a.position.groundDistance(b.position) < reach || a.position.groundDistance(bNext) < reach
                || aNext.groundDistance(b.position) < reach || aNext.groundDistance(bNext) < reach;
    }

    private static int find(int[] parent, int i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }
}
