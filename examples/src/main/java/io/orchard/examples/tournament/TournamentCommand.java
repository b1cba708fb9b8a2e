package io.orchard.examples.tournament;

import io.orchard.examples.OptionsCommand;
import io.orchard.examples.Orchard;
import io.orchard.examples.match.Folders;
import io.orchard.examples.match.Lineup;
import io.orchard.protocol.cli.Options;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Locale;

/**
 * {@code ./orchard tournament --games K --agents Dwarf,Robot,... --seed-from N --time-limit S --out DIR}:
 * plays a {@link Tournament}, showing its progress, then writes results.csv, results.json,
 * results.md and chart.png, prints the table of means and every lockstep turn a game went on
 * without.
 */
public final class TournamentCommand extends OptionsCommand {

    private static final Options OPTIONS = new Options("orchard tournament",
            "Plays K games on K seeds (N, N+1, ...) with the same agents, in lockstep, each agent on its own"
                    + "\nconnection; shows the progress, writes results.csv and results.json (game, seed, agent,"
                    + "\nfruit, points: one row per agent per game) and chart.png (a box plot of the fruit per game"
                    + "\nof each agent) and results.md (the games and the means as Markdown tables), and prints each"
                    + "\nagent's mean and spread. The same seeds and agents give the same results, unless a turn was"
                    + "\nmissed: every missed turn is printed and listed in results.json.")
            .value("games", "K", "how many games, 1 to 1000", "5")
            .value("agents", "NAMES", "the agents, separated by commas: Dwarf, Robot, Bunny, Guppy, Roadrunner,"
                    + " FirstAgent", "Dwarf,Robot,Bunny,Guppy,Roadrunner")
            .value("seed-from", "N", "the seed of the first game", "1")
            .value("time-limit", "SECONDS", "the length of each game in simulated seconds; a game ends sooner when all"
                    + " fruit is collected", "300")
            .value("turn-deadline", "SECONDS", "how long a tick waits for an agent's turn (wall clock) before it goes "
                    + "on without it; such a missed turn is reported", "10")
            .value("out", "DIR", "the folder for the results (default: a new folder tournament-<date>-<time>)",
                    null);

    /** Runs {@code ./orchard tournament} with these arguments. */
    public static void main(String[] args) {
        Orchard.runAndExit("tournament", args);
    }

    /** The {@code ./orchard tournament} command. */
    public TournamentCommand() {
        super("tournament", "play K games over K seeds with chosen agents; results as CSV, JSON and a chart",
                OPTIONS);
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        Options.Parsed options = OPTIONS.parse(args);
        int games = options.integer("games", 1, 1000);
        Lineup lineup = Lineup.parse(options.string("agents"));
        long seedFrom = options.longValue("seed-from", Long.MIN_VALUE, Long.MAX_VALUE - games);
        double timeLimit = options.number("time-limit", 1, 3600);
        Duration turnDeadline = Duration.ofMillis(Math.round(options.number("turn-deadline", 0.001, 3600) * 1000));
        Path dir = options.has("out") ? Folders.given(options.string("out")) : Folders.fresh("tournament");
        Tournament tournament = new Tournament(games, lineup, seedFrom, timeLimit, turnDeadline, dir);
        out.printf(Locale.ROOT, "Tournament: %d game%s, seeds %d to %d, %s, %.0f s each; results in %s%n", games,
                games == 1 ? "" : "s", seedFrom, seedFrom + games - 1, String.join(", ", lineup.names()), timeLimit,
                dir);
        out.flush();
        boolean terminal = System.console() != null && out == System.out;
        List<Played> played = tournament.play(new ProgressBar(out, terminal, games));
        List<Result> results = played.stream().flatMap(game -> game.rows().stream()).toList();
        List<Summary> summaries = lineup.names().stream().map(agent -> Summary.of(agent, results)).toList();
        ResultFiles.writeCsv(results, dir);
        ResultFiles.writeJson(played, dir);
        Files.writeString(dir.resolve(ResultTables.FILE), ResultTables.markdown(played, lineup.names(), summaries),
                StandardCharsets.UTF_8);
        FruitChart.write(results, summaries, String.format(Locale.ROOT, "Fruit per game over %d games (seeds %d to %d"
                + ", %.0f s each)", games, seedFrom, seedFrom + games - 1, timeLimit), dir);
        out.println();
        Summary.printTable(summaries, out);
        List<Played> missing = played.stream().filter(game -> !game.missed().isEmpty()).toList();
        out.println(missing.isEmpty() ? "Missed turns: none"
                : "Missed turns, where a game may play differently another time: " + missing.stream()
                        .map(game -> "game " + game.game() + " (seed " + game.seed() + "): "
                                + Tournament.describe(game.missed()))
                        .collect(java.util.stream.Collectors.joining("; ")));
        out.println("Wrote " + dir.resolve(ResultFiles.CSV) + ", " + dir.resolve(ResultFiles.JSON) + ", "
                + dir.resolve(ResultTables.FILE) + " and " + dir.resolve(FruitChart.FILE));
        return 0;
    }
}
