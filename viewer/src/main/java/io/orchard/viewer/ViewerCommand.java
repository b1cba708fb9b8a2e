package io.orchard.viewer;

import io.orchard.cli.Port;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.ReplayState;
import io.orchard.viewer.state.Shot;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.Spec;

/**
 * The viewer's command line: each option typed and in range as picocli reads it, then the whole
 * checked by {@link #options()}, which refuses combinations that make no sense (a screenshot needs
 * {@code --headless}, {@code --every} needs {@code --out}, a replay takes no host) naming the
 * options and what was expected.
 */
@Command(name = "viewer", abbreviateSynopsis = true, sortOptions = false,
        description = {"Watch the world in 3D, live or from a recording", "",
            "It shows an Orchard world live from a server, or replayed from a recording (the server's --record), "
                    + "in a window, or headless (--headless): rendered off screen, writing screenshots at given "
                    + "simulated times or every so many seconds, or measuring the frame rate, and then exiting."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n", footerHeading = "%n",
        footer = {"Windowed keys: drag to turn the view, right drag to pan, wheel to zoom, W A S D to move, F to fly, "
                + "click an agent to select and follow it, V for its point of view, Enter to send it an instruction, "
                + "L for names, K for shadows, H for help; a live game, with --operator-token: Space pauses and "
                + "continues it, G starts it; replays: Space pauses, + and - change the speed, the arrow keys seek "
                + "10 s, Home goes back to the start.", "",
            "When the connection to a live server ends, the viewer says why and, in a window, connects again "
                + "(unless --no-reconnect).", "",
            "Exit status: 0 done, 1 failed (no server, a render error, the watchdog), 2 bad command line."})
final class ViewerCommand implements Callable<Integer> {

    /** The environment variable that gives the operator token when the command line does not. */
    static final String OPERATOR_TOKEN_VARIABLE = "ORCHARD_OPERATOR_TOKEN";

    @Option(names = "--host", paramLabel = "HOST", defaultValue = "localhost",
            description = "The server's host (default: ${DEFAULT-VALUE})")
    private String host;

    @Option(names = "--port", paramLabel = "N", defaultValue = "" + ViewerOptions.DEFAULT_PORT,
            converter = Port.class, description = "The server's port (default: ${DEFAULT-VALUE})")
    private int port;

    @Option(names = "--token", paramLabel = "SECRET", description = "The server's token, when it requires one")
    private String token;

    @Option(names = "--operator-token", paramLabel = "SECRET", defaultValue = "${env:" + OPERATOR_TOKEN_VARIABLE + "}",
            description = "The server's operator token: Space then pauses and continues the game, G starts it. "
                    + "Also read from " + OPERATOR_TOKEN_VARIABLE + ", out of sight of ps")
    private String operatorToken;

    @Option(names = "--no-reconnect", negatable = false,
            description = "In a window, do not connect again when the connection ends (by default the viewer says "
                    + "why and tries again, waiting longer each time); a headless run never does")
    private boolean noReconnect;

    @Option(names = "--replay", paramLabel = "FILE",
            description = "Play a recording (written by the server's --record) instead of connecting")
    private Path replay;

    @Option(names = "--speed", paramLabel = "X", defaultValue = "1", converter = CommandLines.Speed.class,
            description = "Replay speed, simulated seconds per second, " + ReplayState.MIN_SPEED + " to "
                    + (int) ReplayState.MAX_SPEED + " (default: ${DEFAULT-VALUE})")
    private double speed;

    @Option(names = "--headless",
            description = "Render off screen (needs an X display such as xvfb-run) and exit when done")
    private boolean headless;

    @Option(names = "--size", paramLabel = "WxH", defaultValue = "1280x720", converter = CommandLines.SizeConverter.class,
            description = "Frame size in pixels (default: ${DEFAULT-VALUE})")
    private CommandLines.Size size;

    @Option(names = "--screenshot", paramLabel = "FILE",
            description = "Headless: write a PNG of the frame at the matching --at (repeatable)")
    private List<Path> screenshots = new ArrayList<>();

    @Option(names = "--at", paramLabel = "SECONDS", converter = CommandLines.Time.class,
            description = "Simulated time of the matching --screenshot; without it, at once (repeatable)")
    private List<Double> times = new ArrayList<>();

    @Option(names = "--every", paramLabel = "SECONDS", converter = CommandLines.Every.class,
            description = "Headless: a screenshot every SECONDS of simulated time, into --out")
    private Double every;

    @Option(names = "--out", paramLabel = "DIR", description = "Folder of the --every screenshots")
    private Path out;

    @Option(names = "--until", paramLabel = "SECONDS", converter = CommandLines.Time.class,
            description = "Last time of the --every screenshots (default: the end of the game)")
    private Double until;

    @Option(names = "--camera", paramLabel = "X,Y,Z", converter = CommandLines.Point.class,
            description = "Headless: where the camera stands (default: an overview)")
    private Vec3 camera;

    @Option(names = "--look-at", paramLabel = "X,Y,Z", converter = CommandLines.Point.class,
            description = "Headless: what the camera looks at (default: the world's centre)")
    private Vec3 lookAt;

    @Option(names = "--follow", paramLabel = "AGENT", converter = CommandLines.AgentName.class,
            description = "Select an agent: its view cone is drawn and the camera follows it")
    private String follow;

    @Option(names = "--hud", paramLabel = "on|off", defaultValue = "on", converter = CommandLines.OnOff.class,
            completionCandidates = CommandLines.OnOff.class,
            description = "Draw the panels of text (default: ${DEFAULT-VALUE})")
    private String hud;

    @Option(names = "--shadows", paramLabel = "on|off", defaultValue = "off", converter = CommandLines.OnOff.class,
            completionCandidates = CommandLines.OnOff.class,
            description = "Draw shadow maps (slow in software; flat shades stand in when off) (default: "
                    + "${DEFAULT-VALUE})")
    private String shadows;

    @Option(names = "--timeout", paramLabel = "SECONDS", converter = CommandLines.Timeout.class,
            description = "Headless: give up after this long (default: " + (int) ViewerOptions.BASE_TIMEOUT
                    + ", plus the last --at or --until with a live server)")
    private Double timeout;

    @Option(names = "--measure", paramLabel = "SECONDS", converter = CommandLines.Measure.class,
            description = "Measure frames per second (and the draw calls a frame) over SECONDS of wall-clock time, then exit")
    private Double measure;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream stdout;
    private final PrintStream stderr;

    ViewerCommand(PrintStream stdout, PrintStream stderr) {
        this.stdout = stdout;
        this.stderr = stderr;
    }

    /**
     * Reads and checks a command line without running it.
     *
     * @return the options, or null when the command line asks for help
     * @throws ParameterException naming the bad option and what was expected
     */
    static ViewerOptions parse(List<String> args) {
        CommandLine line = ViewerMain.command(System.out, System.err);
        line.parseArgs(args.toArray(String[]::new));
        return line.isUsageHelpRequested() ? null : line.<ViewerCommand>getCommand().options();
    }

    @Override
    public Integer call() {
        return ViewerMain.show(options(), stdout, stderr);
    }

    /**
     * The options, checked as a whole.
     *
     * @throws ParameterException naming the options that do not go together and what was expected
     */
    ViewerOptions options() {
        ParseResult given = spec.commandLine().getParseResult();
        if (replay != null && (given.hasMatchedOption("--host") || given.hasMatchedOption("--port")
                || given.hasMatchedOption("--token"))) {
            throw wrong("--replay plays a file; --host, --port and --token are for a live server");
        }
        if (replay != null && (given.hasMatchedOption("--operator-token") || noReconnect)) {
            throw wrong("--replay plays a file; --operator-token and --no-reconnect are for a live server");
        }
        if (replay == null && given.hasMatchedOption("--speed")) {
            throw wrong("--speed is for --replay; a live game runs at the server's pace");
        }
        List<Shot> shots = new ArrayList<>();
        if (!times.isEmpty() && times.size() != screenshots.size()) {
            throw wrong("give one --at per --screenshot: " + screenshots.size() + " --screenshot and " + times.size()
                    + " --at");
        }
        for (int i = 0; i < screenshots.size(); i++) {
            shots.add(new Shot(times.isEmpty() ? 0 : times.get(i), screenshots.get(i)));
        }
        if (every != null && out == null) {
            throw wrong("--every needs --out DIR, the folder to write the screenshots to");
        }
        if (every == null && (out != null || until != null)) {
            throw wrong("--out and --until go with --every SECONDS");
        }
        if (every != null && !shots.isEmpty()) {
            throw wrong("give either --screenshot/--at or --every, not both");
        }
        boolean shooting = !shots.isEmpty() || every != null;
        if (shooting && !headless) {
            throw wrong("--screenshot and --every need --headless");
        }
        if (headless && !shooting && measure == null) {
            throw wrong("--headless has nothing to do: give --screenshot FILE, --every SECONDS or --measure SECONDS");
        }
        if (shooting && measure != null) {
            throw wrong("--measure renders as fast as it can; take screenshots in another run");
        }
        if (!headless && (camera != null || lookAt != null)) {
            throw wrong("--camera and --look-at place the headless camera; in a window, move it with the mouse");
        }
        double lastTime = until != null ? until : shots.stream().mapToDouble(Shot::time).max().orElse(0);
        double watchdog = timeout != null ? timeout
                : ViewerOptions.BASE_TIMEOUT + (replay == null ? lastTime : 0) + (measure == null ? 0 : measure)
                        + (replay == null && every != null && until == null ? 600 : 0);
        return new ViewerOptions(host, port, token, operatorToken, replay, speed, headless, size.width(), size.height(),
                shots, every, out, until, camera, lookAt, follow, hud.equals("on"), shadows.equals("on"), watchdog,
                measure, !noReconnect);
    }

    private ParameterException wrong(String message) {
        return new ParameterException(spec.commandLine(), message);
    }
}
