package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

/**
 * The dense grid of a tick's perceptions must visit the agents in a box exactly as the agent grid
 * does, or the agents in a perception would come in another order: on crowds packed and spread,
 * including ones spread too thin for a dense grid.
 */
class CrowdGridTest {

    private static final double CELL = 25;

    private static Map<String, Agent> crowd(SplittableRandom random, int count, double spread) {
        Map<String, Agent> agents = new TreeMap<>();
        FakeSession owner = new FakeSession(1, Role.AGENT);
        for (int i = 0; i < count; i++) {
            // Some on cell borders and on the same spot, where order within a cell shows.
            double x = random.nextInt(5) == 0 ? CELL * random.nextInt(-4, 4) : random.nextDouble(-spread, spread);
            double z = random.nextInt(5) == 0 ? CELL * random.nextInt(-4, 4) : random.nextDouble(-spread, spread);
            String name = "A" + random.nextInt(1_000_000);
            agents.put(name, new Agent(name, owner, TestWorlds.BODY, null, Vec3.ground(x, z), 0, null));
        }
        return agents;
    }

    private static void visitsAsTheAgentGrid(Map<String, Agent> agents, SplittableRandom random, double spread) {
        AgentGrid reference = new AgentGrid(agents.values(), CELL);
        CrowdGrid.Query dense = CrowdGrid.of(agents.values(), CELL);
        int visited = 0;
        int nearSomeone = 0;
        List<Agent> all = new ArrayList<>(agents.values());
        for (int query = 0; query < 300; query++) {
            // Around an agent mostly, so that boxes in a thinly spread crowd find someone too.
            Agent near = all.get(random.nextInt(all.size()));
            boolean anywhere = random.nextInt(4) == 0;
            double w = random.nextDouble(0, 120);
            double d = random.nextDouble(0, 120);
            double x = anywhere ? random.nextDouble(-spread * 1.2, spread * 1.2) : near.position.x() - random.nextDouble(0, w);
            double z = anywhere ? random.nextDouble(-spread * 1.2, spread * 1.2) : near.position.z() - random.nextDouble(0, d);
            nearSomeone += anywhere ? 0 : 1;
            List<String> expected = new ArrayList<>();
            reference.forEachInBox(x, z, x + w, z + d, agent -> expected.add(agent.name + "@" + agent.position.x()
                    + "," + agent.position.z()));
            List<String> found = new ArrayList<>();
            dense.forEachInBox(x, z, x + w, z + d, (agent, ax, az) -> found.add(agent.name + "@" + ax + "," + az));
            assertThat(found).as("box at (%s, %s), %s by %s", x, z, w, d).isEqualTo(expected);
            visited += found.size();
        }
        assertThat(visited).as("agents visited in all the boxes").isGreaterThanOrEqualTo(nearSomeone);
    }

    @Test
    void aPackedCrowdIsVisitedAsTheAgentGridVisitsIt() {
        SplittableRandom random = new SplittableRandom(4);
        for (int round = 0; round < 20; round++) {
            visitsAsTheAgentGrid(crowd(random, random.nextInt(1, 400), 200), random, 200);
        }
    }

    @Test
    void aCrowdTooSpreadForADenseGridIsVisitedAsTheAgentGridVisitsIt() {
        SplittableRandom random = new SplittableRandom(5);
        visitsAsTheAgentGrid(crowd(random, 50, 1e6), random, 1e6);
    }

    @Test
    void noAgentsMeansNothingToVisit() {
        List<Agent> seen = new ArrayList<>();
        CrowdGrid.of(List.of(), CELL).forEachInBox(-100, -100, 100, 100, (agent, x, z) -> seen.add(agent));
        assertThat(seen).isEmpty();
    }
}
