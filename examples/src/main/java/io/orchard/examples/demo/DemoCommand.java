package io.orchard.examples.demo;

import io.orchard.examples.OptionsCommand;
import io.orchard.examples.Orchard;
import io.orchard.examples.match.Folders;
import io.orchard.protocol.cli.Options;
import io.orchard.protocol.cli.UsageException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * {@code ./orchard demo [--seed N] [--time-limit S] [--headless] [--out DIR]}: runs a {@link Demo},
 * a whole match of the paper's five agents with a viewer, and prints the ranking.
 */
public final class DemoCommand extends OptionsCommand {

    /** Simulated seconds between the headless viewer's screenshots. */
    static final double EVERY = 10;

    private static final Options OPTIONS = new Options("orchard demo",
            "Runs a whole match in this one process: a world server with a fresh seed (printed), the paper's five"
                    + "\nagents, and the viewer, in a window when there is a display, headless otherwise, writing a"
                    + "\nscreenshot every " + (int) EVERY + " s of the game and one of its end to a folder it names."
                    + "\nThe game ends at the time limit or when all fruit is collected, and the ranking is printed."
                    + "\n\nHeadless without a display needs xvfb-run (Debian/Ubuntu: apt-get install xvfb xauth).")
            .value("seed", "N", "seed of the world; drawn and printed when absent", null)
            .value("time-limit", "SECONDS", "length of the game in simulated (here: wall-clock) seconds", "300")
            .flag("headless", "render off screen and write screenshots, even where there is a display")
            .value("out", "DIR", "folder of the screenshots (default: a new folder demo-<date>-<time>)", null);

    /** Runs {@code ./orchard demo} with these arguments. */
    public static void main(String[] args) {
        Orchard.runAndExit("demo", args);
    }

    /** The {@code ./orchard demo} command. */
    public DemoCommand() {
        super("demo", "run a whole match: a server, the five agents and the viewer, then the ranking", OPTIONS);
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        Options.Parsed options = OPTIONS.parse(args);
        Long seed = options.longValue("seed", Long.MIN_VALUE, Long.MAX_VALUE);
        double timeLimit = options.number("time-limit", 1, 86_400);
        boolean display = hasDisplay();
        boolean headless = options.has("headless") || !display;
        if (!headless && options.has("out")) {
            throw new UsageException("--out is the folder of the headless viewer's screenshots; add --headless to "
                    + "write them (in a window there are none)");
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
        if (!options.has("headless") && headless) {
            out.println("No display: the viewer runs headless.");
        }
        Path dir = !headless ? null : options.has("out") ? Folders.given(options.string("out")) : Folders.fresh("demo");
        return new Demo(seed, timeLimit, headless, dir, xvfbRun, EVERY).play(out, err);
    }

    /** Whether a window can be opened here: on Linux only with an X or Wayland display. */
    static boolean hasDisplay() {
        boolean linux = System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("linux");
        return !linux || System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null;
    }
}
