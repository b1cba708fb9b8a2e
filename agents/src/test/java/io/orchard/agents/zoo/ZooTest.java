package io.orchard.agents.zoo;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.AgentStats;
import io.orchard.agents.Games;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Point2;
import io.orchard.server.sim.GameListener;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** The paper's five agents in real lockstep games: alone, together, and told what to do. */
class ZooTest {

    static final long SEED = 1998;

    /** Fewer than this share of an agent's moves may be refused because it ran into something. */
    static final double MAX_OBSTACLE_REJECTIONS = 0.05;

    @Nested
    class Alone {

        @ParameterizedTest(name = "{0}")
        @EnumSource(Species.class)
        void eachAgentAloneCollectsAtLeastFiveFruitInThreeMinutes(Species species) throws Exception {
            AgentController agent = species.create();

            Games.play(SEED, 180, List.of(agent));

            AgentStats stats = agent.stats();
            assertThat(stats.fruit()).as("%s: %s", species, stats).isGreaterThanOrEqualTo(5);
            assertThat(stats.obstacleRejectionRate()).as("%s: %s", species, stats).isLessThan(MAX_OBSTACLE_REJECTIONS);
            assertThat(stats.errors()).as("%s: %s", species, stats).isZero();
        }
    }

    @Nested
    class Together {

        /**
         * All five in the world of the seed for 300 simulated seconds (the server's default game).
         * Reachable fruit: every generated fruit can be grasped from free ground beside it (the
         * world generator guarantees it), so a fruit is reachable when some agent's gripper
         * reaches its height.
         */
        @Test
        void allFiveCollectNineTenthsOfTheReachableFruit() throws Exception {
            List<AgentController> agents = new ArrayList<>();
            for (Species species : Species.values()) {
                agents.add(species.create());
            }

            Games.Result game = Games.play(SEED, 300, agents);

            List<Gripper> grippers = agents.stream().map(a -> a.declaredBody().body().gripper()).toList();
            List<FruitState> fruit = Games.fruitOf(SEED);
            long reachable = fruit.stream().filter(f -> grippers.stream()
                    .anyMatch(g -> g.reachesHeight(f.position().y()))).count();
            assertThat(fruit).hasSize(game.fruitAtStart());
            assertThat(game.fruitEaten()).as("fruit eaten of %d reachable", reachable)
                    .isGreaterThanOrEqualTo((int) Math.ceil(0.9 * reachable));
            for (AgentController agent : agents) {
                assertThat(agent.stats().obstacleRejectionRate()).as("%s: %s", agent.name(), agent.stats())
                        .isLessThan(MAX_OBSTACLE_REJECTIONS);
            }
        }
    }

    @Nested
    class Instructed {

        private final Point2[] walk = Games.freeWalk(SEED, 9);

        @ParameterizedTest(name = "{0}")
        @EnumSource(Species.class)
        void eachAgentGoesWhereItIsToldSaysSoAndReturnsToItsAutonomy(Species species) throws Exception {
            AgentController agent = species.create();
            List<String> said = new CopyOnWriteArrayList<>();
            int[] fruitOnArrival = {-1};
            agent.addSpeechListener(text -> {
                said.add(text);
                if (text.startsWith("I'm at the tree") && fruitOnArrival[0] < 0) {
                    fruitOnArrival[0] = agent.stats().fruit();
                }
            });
            agent.instruct("walk to the nearest tree");

            Games.play(SEED, 90, List.of(agent), Games.at(Map.of(agent.name(), walk[0].at(0))));

            assertThat(said).as("what %s said", species).hasSizeGreaterThanOrEqualTo(2);
            assertThat(said.get(0)).as("the answer to the instruction").isEqualTo("Going to the nearest tree.");
            assertThat(said).as("the report").anyMatch(text -> text.startsWith("I'm at the tree ")
                    && text.endsWith("Carrying on by myself."));
            assertThat(said).as("nothing went wrong").noneMatch(text -> text.contains("can't"));
            assertThat(fruitOnArrival[0]).isNotNegative();
            assertThat(agent.stats().fruit()).as("fruit collected after arriving").isGreaterThan(fruitOnArrival[0]);
        }

        @ParameterizedTest(name = "{0}")
        @EnumSource(Species.class)
        void eachAgentStopsWhenToldAndCarriesOnWhenToldAgain(Species species) throws Exception {
            AgentController agent = species.create();
            agent.instruct("stop");
            int[] movesWhileStopped = {-1};
            GameListener teacher = new GameListener() {
                @Override
                public void tickEnded(long tick, double time) {
                    if (tick == 100) { // five seconds of standing still, then carry on
                        movesWhileStopped[0] = agent.stats().movesSent();
                        agent.instruct("carry on");
                    }
                }
            };

            Games.play(SEED, 60, List.of(agent), (name, radius) -> null, teacher);

            assertThat(movesWhileStopped[0]).as("moves while told to stop").isZero();
            assertThat(agent.stats().fruit()).as("fruit once told to carry on").isPositive();
        }
    }
}
