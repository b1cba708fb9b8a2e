package io.orchard.agents.zoo;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.Games;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * No agent of the zoo stays idle or goes back and forth while it has fruit to collect, read from
 * the server's recording of a lockstep game of the agent alone.
 *
 * <p>What counts, as {@link Progress} reads it from the recording:
 * <ul>
 *   <li><b>reachable fruit</b>: still in the world, its centre within the agent's gripper heights,
 *       and a walk leads to a spot within reach of it in the recorded world (the snapshot's trees,
 *       tables, castle, river and bridges, checked with the server's own geometry). The walk goes
 *       around everything, so a fruit behind a refused move stays reachable: the agent must go
 *       around the obstacle or choose another fruit;
 *   <li><b>the agent's chosen fruit</b>: the reachable fruit nearest by walking distance among those
 *       the agent has perceived (the nearest of all while it has perceived none), taken at the
 *       start of each stretch and kept until the next progress;
 *   <li><b>progress</b>: a grasp; the walking distance to the chosen fruit shrinking by at least 1
 *       unit; or, while some reachable fruit has not been perceived yet, looking at ground not
 *       looked at before. An agent that stands still, or walks back and forth over the same ground,
 *       makes none;
 *   <li><b>the limit</b>: no stretch of more than {@value #LIMIT} simulated seconds without
 *       progress while reachable fruit remains.
 * </ul>
 *
 * <p>Every build plays seeds 1 to {@code orchard.progress.seeds} (default {@value #SEEDS}) for each of
 * the five agents, {@code orchard.progress.seconds} (default {@value #SECONDS}) simulated seconds each,
 * the two games that first broke the limit at full length, and the first 65 s of a game that broke
 * it later; the {@code soak} profile of the
 * agents' pom plays every agent for whole games on a hundred seeds
 * ({@code ./mvnw -B -pl agents -am test -Psoak}).
 */
class ProgressTest {

    /** The longest a stretch without progress may last, in simulated seconds. */
    static final double LIMIT = 10;

    static final int SEEDS = 6;
    static final double SECONDS = 30;
    static final double FULL_GAME = 180;

    @TempDir
    Path dir;

    static Stream<Arguments> games() {
        int seeds = Integer.getInteger("orchard.progress.seeds", SEEDS);
        return Stream.of(Species.values())
                .flatMap(species -> LongStream.rangeClosed(1, seeds).mapToObj(seed -> Arguments.of(species, seed)));
    }

    @ParameterizedTest(name = "{0} alone, seed {1}")
    @MethodSource("games")
    void eachAgentAloneMakesProgressWhileReachableFruitRemains(Species species, long seed) throws Exception {
        double seconds = Double.parseDouble(System.getProperty("orchard.progress.seconds", String.valueOf(SECONDS)));

        Progress.Stretch longest = longestStretch(species, seed, seconds);

        assertThat(longest == null ? 0 : longest.seconds()).as("%s alone on seed %d: %s", species, seed, longest)
                .isLessThanOrEqualTo(LIMIT);
    }

    /** Games that broke the limit, as long as it takes to see it: the first two at full length. */
    @Nested
    class Observed {

        @Test
        void theRoadrunnerRefusedByTheCastleGoesAroundIt() throws Exception {
            Progress.Stretch longest = longestStretch(Species.ROADRUNNER, 8, FULL_GAME);

            assertThat(longest == null ? 0 : longest.seconds()).as("Roadrunner alone on seed 8: %s", longest)
                    .isLessThanOrEqualTo(LIMIT);
        }

        @Test
        void theBunnyDoesNotHopBackAndForthAtABridge() throws Exception {
            Progress.Stretch longest = longestStretch(Species.BUNNY, 1, FULL_GAME);

            assertThat(longest == null ? 0 : longest.seconds()).as("Bunny alone on seed 1: %s", longest)
                    .isLessThanOrEqualTo(LIMIT);
        }

        /**
         * Guppy, having seen the western bank, walked 10.6 s up its edge towards a last corner
         * not yet seen, while the rest of the world across the river, all its fruit, waited: the
         * explorer took the river for 60 units more of walking instead of measuring the way.
         */
        @Test
        void guppyAtTheWesternEdgeHeadsWhereItSeesSomethingNew() throws Exception {
            Progress.Stretch longest = longestStretch(Species.GUPPY, 9, 65);

            assertThat(longest == null ? 0 : longest.seconds()).as("Guppy alone on seed 9: %s", longest)
                    .isLessThanOrEqualTo(LIMIT);
        }
    }

    private Progress.Stretch longestStretch(Species species, long seed, double seconds) throws Exception {
        AgentController agent = species.create();
        Path recording = dir.resolve(species.agentName() + "-" + seed + ".ndjson");
        Games.recorded(seed, seconds, List.of(agent), recording);
        Recording game = Recording.read(recording, agent.name());
        assertThat(game.ticks()).as("the ticks of %s's game in the recording", agent.name()).isNotEmpty();
        return Progress.longest(game);
    }
}
