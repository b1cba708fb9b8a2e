package io.orchard.examples.tournament;

import java.util.List;
import java.util.Locale;

/**
 * A tournament's results as Markdown tables, results.md: one row per game (its seed, the fruit, how
 * much was collected and how fast, each agent's fruit, the share of moves refused by an obstacle,
 * the turns missed), then one row per agent (the mean, spread and range of its fruit, its mean
 * points). docs/agents.md shows the tables of a 20-game tournament as this class writes them, and a
 * test checks them against a replay.
 */
final class ResultTables {

    static final String FILE = "results.md";

    private ResultTables() {}

    /** Both tables, the games' then the agents', with a blank line between. */
    static String markdown(List<Played> played, List<String> agents, List<Summary> summaries) {
        StringBuilder text = new StringBuilder(gameHeader(agents));
        played.forEach(game -> text.append(gameRow(game)).append('\n'));
        text.append("\n| agent | games | fruit per game, mean | standard deviation | fewest | most "
                + "| points per game, mean |\n|---|---|---|---|---|---|---|\n");
        for (Summary s : summaries) {
            text.append(String.format(Locale.ROOT, "| %s | %d | %.2f | %.2f | %d | %d | %.2f |%n", s.agent(),
                    s.games(), s.meanFruit(), s.sdFruit(), s.minFruit(), s.maxFruit(), s.meanPoints()));
        }
        return text.toString();
    }

    /** The header of the games' table, with a column for each agent, and its rule. */
    static String gameHeader(List<String> agents) {
        return "| seed | fruit | collected together | " + String.join(" | ", agents)
                + " | moves refused by an obstacle | missed turns |\n|---|---|---|"
                + "---|".repeat(agents.size()) + "---|---|\n";
    }

    /** One game's row, without its line end. */
    static String gameRow(Played game) {
        StringBuilder row = new StringBuilder(String.format(Locale.ROOT, "| %d | %d | %d in %.0f s |", game.seed(),
                game.fruitAtStart(), game.collected(), game.seconds()));
        game.rows().forEach(r -> row.append(' ').append(r.fruit()).append(" |"));
        row.append(String.format(Locale.ROOT, " %.2f %% | %d |", 100.0 * game.refused() / Math.max(1, game.moves()),
                game.missed().size()));
        return row.toString();
    }
}
