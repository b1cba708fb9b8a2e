package io.orchard.examples.embedded;

import io.orchard.cli.Decimal;
import io.orchard.cli.Seed;
import io.orchard.examples.OptionValues;
import java.io.PrintStream;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code ./orchard embedded [--seed N] [--time-limit SECONDS]}: runs {@link EmbeddedGame}. */
@Command(name = "embedded", abbreviateSynopsis = true, sortOptions = false,
        description = {"Run a server and two agents embedded in one JVM", "",
            "It runs io.orchard.examples.embedded.EmbeddedGame: a world server in this JVM on a free port, Dwarf and "
                    + "Robot on threads of the same JVM in lockstep, the game's events as they happen, and the "
                    + "ranking."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
public final class EmbeddedCommand implements Callable<Integer> {

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1998", converter = Seed.class,
            description = "Seed of the world (default: ${DEFAULT-VALUE})")
    private long seed;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "60", converter = TimeLimit.class,
            description = "Length of the game in simulated seconds (default: ${DEFAULT-VALUE})")
    private double timeLimit;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    private final PrintStream out;

    /** The {@code ./orchard embedded} command, printing to {@code out}. */
    public EmbeddedCommand(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() throws Exception {
        EmbeddedGame.play(seed, timeLimit, out);
        return 0;
    }

    /** A game of 1 s to an hour. */
    static final class TimeLimit extends Decimal {
        TimeLimit() {
            super(1, 3600, "1-3600 seconds");
        }
    }
}
