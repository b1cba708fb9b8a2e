package io.orchard.examples.tournament;

import io.orchard.cli.Decimal;
import io.orchard.cli.Seed;
import io.orchard.cli.Whole;
import io.orchard.examples.OptionValues;
import io.orchard.examples.Orchard;
import io.orchard.examples.match.Folders;
import io.orchard.examples.firstagent.FirstAgent;
import io.orchard.examples.match.Lineup;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code ./orchard tournament --games K --agents Dwarf,Robot,... --seed-from N --time-limit S --out DIR}:
 * plays a {@link Tournament}, showing its progress, then writes results.csv, results.json,
 * results.md and chart.png, prints the table of means and every lockstep turn a game went on
 * without.
 */
@Command(name = "tournament", abbreviateSynopsis = true, sortOptions = false,
        description = {"Play K games on K seeds; results as CSV, JSON and a chart", "",
            "It plays K games on K seeds (N, N+1, ...) with the same agents, in lockstep, each agent on its own "
                    + "connection; shows the progress, writes results.csv and results.json (game, seed, agent, fruit, "
                    + "points: one row per agent per game), chart.png (a box plot of the fruit per game of each "
                    + "agent) and results.md (the games and the means as Markdown tables), and prints each agent's "
                    + "mean and spread. The same seeds and agents give the same results, unless a turn was missed: "
                    + "every missed turn is printed and listed in results.json."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
public final class TournamentCommand implements Callable<Integer> {

    @Option(names = "--games", paramLabel = "K", defaultValue = "5", converter = Games.class,
            description = "How many games, 1 to 1000 (default: ${DEFAULT-VALUE})")
    private int games;

    @Option(names = "--agents", paramLabel = "NAMES", defaultValue = "Dwarf,Robot,Bunny,Guppy,Roadrunner",
            converter = Agents.class, description = "The agents, separated by commas: Dwarf, Robot, Bunny, Guppy, "
                    + "Roadrunner, FirstAgent (default: ${DEFAULT-VALUE})")
    private Lineup lineup;

    @Option(names = "--seed-from", paramLabel = "N", defaultValue = "1", converter = Seed.class,
            description = "The seed of the first game (default: ${DEFAULT-VALUE})")
    private long seedFrom;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "300", converter = TimeLimit.class,
            description = "The length of each game in simulated seconds; a game ends sooner when all fruit is "
                    + "collected (default: ${DEFAULT-VALUE})")
    private double timeLimit;

    @Option(names = "--turn-deadline", paramLabel = "SECONDS", defaultValue = "10", converter = TurnDeadline.class,
            description = "How long a tick waits for an agent's turn (wall clock) before it goes on without it; such a "
                    + "missed turn is reported (default: ${DEFAULT-VALUE})")
    private double turnDeadline;

    @Option(names = "--out", paramLabel = "DIR",
            description = "The folder for the results (default: a new folder tournament-<date>-<time>)")
    private Path outDir;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;

    /** Runs {@code ./orchard tournament} with these arguments. */
    public static void main(String[] args) {
        Orchard.runAndExit("tournament", args);
    }

    /** The {@code ./orchard tournament} command, printing to {@code out}. */
    public TournamentCommand(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() throws Exception {
        if (seedFrom > Long.MAX_VALUE - games) {
            throw new ParameterException(spec.commandLine(), "invalid value for option '--seed-from': '" + seedFrom
                    + "' is out of range (expected at most " + (Long.MAX_VALUE - games) + ", so that the seeds of "
                    + games + " games fit in 64 bits)");
        }
        Path dir = outDir != null ? Folders.given(outDir) : Folders.fresh("tournament");
        Tournament tournament = new Tournament(games, lineup, seedFrom, timeLimit,
                Duration.ofMillis(Math.round(turnDeadline * 1000)), dir);
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

    /** 1 to 1000 games. */
    static final class Games extends Whole {
        Games() {
            super(1, 1000, "1-1000 games");
        }
    }

    /** A game of 1 s to an hour. */
    static final class TimeLimit extends Decimal {
        TimeLimit() {
            super(1, 3600, "1-3600 seconds");
        }
    }

    /** A turn deadline of a millisecond to an hour. */
    static final class TurnDeadline extends Decimal {
        TurnDeadline() {
            super(0.001, 3600, "0.001-3600 seconds");
        }
    }

    /** The agents named in a comma-separated list. */
    static final class Agents implements ITypeConverter<Lineup> {
        @Override
        public Lineup convert(String list) {
            try {
                return Lineup.parse(list, Map.of("FirstAgent", () -> new FirstAgent("FirstAgent")));
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }
}
