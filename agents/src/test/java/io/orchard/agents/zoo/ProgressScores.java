package io.orchard.agents.zoo;

import io.orchard.agents.AgentController;
import io.orchard.agents.Games;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;

/**
 * Measures for docs/agents.md what {@link ProgressTest} checks: each agent alone on seeds 1 to
 * {@code orchard.progress.seeds} (default 20) for 180 simulated seconds, the longest stretch
 * without progress ({@link Progress}) and the games over the limit. Takes a quarter of an hour on
 * two cores, so it runs only when asked:
 * {@code ./mvnw -pl agents test -Dtest=ProgressScores -Dorchard.scores=true}.
 */
class ProgressScores {

    static final double SECONDS = 180;

    @Test
    @EnabledIfSystemProperty(named = "orchard.scores", matches = "true")
    void measure() throws Exception {
        int seeds = Integer.getInteger("orchard.progress.seeds", 20);
        Path dir = Files.createTempDirectory("orchard-progress");
        StringBuilder table = new StringBuilder("| agent | games | longest stretch without progress | seed |"
                + " games over " + ProgressTest.LIMIT + " s |\n|---|---|---|---|---|\n");
        for (Species species : Species.values()) {
            List<double[]> stretches = new ArrayList<>();
            for (long seed = 1; seed <= seeds; seed++) {
                AgentController agent = species.create();
                Path recording = dir.resolve(agent.name() + "-" + seed + ".ndjson");
                Games.recorded(seed, SECONDS, List.of(agent), recording);
                Progress.Stretch longest = Progress.longest(Recording.read(recording, agent.name()));
                Files.delete(recording);
                stretches.add(new double[] {longest == null ? 0 : longest.seconds(), seed});
                System.out.printf(Locale.ROOT, "%s seed %d: %s%n", species.agentName(), seed, longest);
            }
            double[] worst = stretches.stream().max(Comparator.comparingDouble(s -> s[0])).orElseThrow();
            table.append(String.format(Locale.ROOT, "| %s | %d | %.1f s | %d | %d |%n", species.agentName(), seeds,
                    worst[0], (long) worst[1], stretches.stream().filter(s -> s[0] > ProgressTest.LIMIT).count()));
        }
        Files.delete(dir);
        System.out.println(table);
    }
}
