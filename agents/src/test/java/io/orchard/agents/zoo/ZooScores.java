package io.orchard.agents.zoo;

import io.orchard.agents.AgentController;
import io.orchard.agents.AgentStats;
import io.orchard.agents.Games;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;

/**
 * Measures the zoo for docs/agents.md: each agent alone for 180 simulated seconds on seeds 1 to
 * 10 (fruit per simulated minute, refused moves). The five together are measured by the
 * tournament, whose tables docs/agents.md shows. Takes a few minutes, so it runs only when asked:
 * {@code ./mvnw -pl agents test -Dtest=ZooScores -Dorchard.scores=true}.
 */
class ZooScores {

    static final int SEEDS = 10;
    static final double ALONE_SECONDS = 180;

    @Test
    @EnabledIfSystemProperty(named = "orchard.scores", matches = "true")
    void measure() throws Exception {
        StringBuilder table = new StringBuilder();
        table.append("| agent | fruit per minute alone (mean of ").append(SEEDS).append(" seeds) | lowest | highest"
                + " | points per minute | moves refused by an obstacle |\n|---|---|---|---|---|---|\n");
        for (Species species : Species.values()) {
            List<Double> perMinute = new ArrayList<>();
            double points = 0;
            long moves = 0;
            long refused = 0;
            for (long seed = 1; seed <= SEEDS; seed++) {
                AgentController agent = species.create();
                Games.Result game = Games.play(seed, ALONE_SECONDS, List.of(agent));
                AgentStats stats = agent.stats();
                double minutes = minutes(game);
                perMinute.add(stats.fruit() / minutes);
                points += stats.points() / minutes;
                moves += stats.movesSent();
                refused += stats.obstacleRejections();
            }
            table.append(String.format(Locale.ROOT, "| %s | %.2f | %.2f | %.2f | %.2f | %.2f %% |%n", species.agentName(),
                    perMinute.stream().mapToDouble(d -> d).average().orElse(0),
                    perMinute.stream().mapToDouble(d -> d).min().orElse(0),
                    perMinute.stream().mapToDouble(d -> d).max().orElse(0), points / SEEDS,
                    100.0 * refused / Math.max(1, moves)));
        }
        System.out.println(table);
    }

    /** The game's length in simulated minutes: shorter than the limit when the fruit ran out. */
    private static double minutes(Games.Result game) {
        return (game.over().tick() + 1) / 20.0 / 60;
    }
}
