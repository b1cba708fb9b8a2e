package io.orchard.examples.demo;

import io.orchard.cli.Decimal;
import io.orchard.cli.Seed;
import io.orchard.examples.OptionValues;
import io.orchard.examples.Orchard;
import io.orchard.examples.match.Folders;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code ./orchard demo [--seed N] [--time-limit S] [--headless] [--out DIR]}: runs a {@link Demo},
 * a whole match of the paper's five agents with a viewer, and prints the ranking.
 */
@Command(name = "demo", abbreviateSynopsis = true, sortOptions = false,
        description = {"Run a whole match: a server, the five agents, the viewer", "",
            "It runs in this one process: a world server with a fresh seed (printed), the paper's five agents, and "
                    + "the viewer, in a window when there is a display, headless otherwise, writing a screenshot "
                    + "every " + (int) DemoCommand.EVERY + " s of the game and one of its end to a folder it names. "
                    + "The game ends at the time limit or when all fruit is collected, and the ranking is printed.",
            "",
            "Headless without a display needs xvfb-run (Debian/Ubuntu: apt-get install xvfb xauth)."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
public final class DemoCommand implements Callable<Integer> {

    /** Simulated seconds between the headless viewer's screenshots. */
    static final double EVERY = 10;

    @Option(names = "--seed", paramLabel = "N", converter = Seed.class,
            description = "Seed of the world; drawn and printed when absent")
    private Long seed;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "300", converter = TimeLimit.class,
            description = "Length of the game in simulated (here: wall-clock) seconds (default: ${DEFAULT-VALUE})")
    private double timeLimit;

    @Option(names = "--headless", description = "Render off screen and write screenshots, even where there is a display")
    private boolean headless;

    @Option(names = "--web", description = "Serve the browser viewer too: print its address, and open it where there"
            + " is a desktop")
    private boolean web;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Folder of the screenshots (default: a new folder demo-<date>-<time>)")
    private Path dir;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;
    private final PrintStream err;

    /** Runs {@code ./orchard demo} with these arguments. */
    public static void main(String[] args) {
        Orchard.runAndExit("demo", args);
    }

    /** The {@code ./orchard demo} command, printing to these streams. */
    public DemoCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() throws Exception {
        boolean display = hasDisplay();
        boolean headless = this.headless || !display;
        if (!headless && dir != null) {
            throw new ParameterException(spec.commandLine(), "--out is the folder of the headless viewer's "
                    + "screenshots; add --headless to write them (in a window there are none)");
        }
        Path xvfbRun = null;
        if (headless && !display) {
            xvfbRun = HeadlessViewer.xvfbRun();
            if (xvfbRun == null) {
                err.println("orchard demo: there is no display (DISPLAY is not set), and the headless viewer needs"
                        + " xvfb-run for a virtual one, which is not installed: install xvfb and xauth (Debian/Ubuntu:"
                        + " apt-get install xvfb xauth), or run on a desktop");
                return 1;
            }
        }
        if (!this.headless && headless) {
            out.println("No display: the viewer runs headless.");
        }
        Path folder = !headless ? null : dir != null ? Folders.given(dir) : Folders.fresh("demo");
        return new Demo(seed, timeLimit, headless, folder, xvfbRun, EVERY, web).play(out, err);
    }

    /** A game of 1 s to a day. */
    static final class TimeLimit extends Decimal {
        TimeLimit() {
            super(1, 86_400, "1-86400 seconds");
        }
    }

    /** Whether a window can be opened here: on Linux only with an X or Wayland display. */
    static boolean hasDisplay() {
        boolean linux = System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("linux");
        return !linux || System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null;
    }
}
