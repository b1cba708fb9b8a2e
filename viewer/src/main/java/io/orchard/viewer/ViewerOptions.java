package io.orchard.viewer;

import io.orchard.protocol.cli.Options;
import io.orchard.protocol.cli.UsageException;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.ReplayState;
import io.orchard.viewer.state.Shot;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The viewer's command line, checked as a whole: every value in range and every combination
 * meaningful (a screenshot needs {@code --headless}, {@code --every} needs {@code --out}, a replay
 * takes no host), with errors that name the option and what was expected.
 *
 * @param host     the server's host
 * @param port     the server's port
 * @param token    the server's shared secret, or null
 * @param replay   a recording to play instead of connecting, or null
 * @param speed    replay speed: simulated seconds per second
 * @param headless render off screen and exit when done
 * @param width    frame width in pixels
 * @param height   frame height in pixels
 * @param shots    screenshots at given times
 * @param every    seconds between periodic screenshots, or null
 * @param out      folder of periodic screenshots, or null
 * @param until    last time of periodic screenshots, or null for the end
 * @param camera   where a headless camera stands, or null
 * @param lookAt   what a headless camera looks at, or null
 * @param follow   an agent to select and follow, or null
 * @param hud      whether the panels of text are drawn
 * @param shadows  whether shadows are drawn
 * @param timeout  seconds after which a headless run is stopped as failed
 * @param measure  seconds of frame-rate measure, or null
 */
public record ViewerOptions(String host, int port, String token, Path replay, double speed, boolean headless,
                            int width, int height, List<Shot> shots, Double every, Path out, Double until,
                            Vec3 camera, Vec3 lookAt, String follow, boolean hud, boolean shadows, double timeout,
                            Double measure) {

    /** The port the viewer connects to unless told otherwise (the server's default). */
    public static final int DEFAULT_PORT = 7557;

    /** The headless watchdog's base time in seconds, before the time the viewer must wait for a live game. */
    public static final double BASE_TIMEOUT = 60;

    static final Options OPTIONS = new Options("orchard viewer",
            "Shows an Orchard world in 3D: live from a server, or replayed from a recording; in a window, or "
                    + "headless, writing screenshots.")
            .value("host", "HOST", "the server's host", "localhost")
            .value("port", "N", "the server's port", String.valueOf(DEFAULT_PORT))
            .value("token", "SECRET", "the server's token, when it requires one", null)
            .value("replay", "FILE", "play a recording (written by the server's --record) instead of connecting",
                    null)
            .value("speed", "X", "replay speed, simulated seconds per second (" + ReplayState.MIN_SPEED + " to "
                    + (int) ReplayState.MAX_SPEED + ")", "1")
            .flag("headless", "render off screen (needs an X display such as xvfb-run) and exit when done")
            .value("size", "WxH", "frame size in pixels", "1280x720")
            .repeatable("screenshot", "FILE", "headless: write a PNG of the frame at the matching --at")
            .repeatable("at", "SECONDS", "simulated time of the matching --screenshot (default: at once)")
            .value("every", "SECONDS", "headless: a screenshot every SECONDS of simulated time, into --out", null)
            .value("out", "DIR", "folder of the --every screenshots", null)
            .value("until", "SECONDS", "last time of the --every screenshots (default: the end of the game)", null)
            .value("camera", "X,Y,Z", "headless: where the camera stands (default: an overview)", null)
            .value("look-at", "X,Y,Z", "headless: what the camera looks at (default: the world's centre)", null)
            .value("follow", "AGENT", "select an agent: its view cone is drawn and the camera follows it", null)
            .value("hud", "on|off", "draw the panels of text", "on")
            .value("shadows", "on|off", "draw shadow maps (slow in software; flat shades stand in when off)",
                    "off")
            .value("timeout", "SECONDS", "headless: give up after this long (default: " + (int) BASE_TIMEOUT
                    + ", plus the last --at or --until with a live server)", null)
            .value("measure", "SECONDS", "measure frames per second over SECONDS of wall-clock time, then exit",
                    null);

    /** Keeps its own unmodifiable copy of the lists. */
    public ViewerOptions {
        shots = List.copyOf(shots);
    }

    /** The help text. */
    static String help() {
        return OPTIONS.help() + """

                Windowed keys: drag to turn the view, right drag to pan, wheel to zoom, W A S D to move,
                F to fly, click an agent to select and follow it, V for its point of view, Enter to send
                it an instruction, L for names, K for shadows, H for help; replays: Space pauses, + and -
                change the speed, the arrow keys seek 10 s, Home goes back to the start.

                Exit status: 0 done, 1 failed (no server, a render error, the watchdog), 2 bad command line.
                """;
    }

    /**
     * Reads and checks a command line.
     *
     * @throws UsageException naming the bad option and what was expected
     */
    static ViewerOptions parse(List<String> args) throws UsageException {
        Options.Parsed given = OPTIONS.parse(args);
        if (given.help()) {
            return null;
        }
        Path replay = given.has("replay") ? Path.of(given.string("replay")) : null;
        if (replay != null && (given.has("host") || given.has("port") || given.has("token"))) {
            throw new UsageException("--replay plays a file; --host, --port and --token are for a live server");
        }
        if (replay == null && given.has("speed")) {
            throw new UsageException("--speed is for --replay; a live game runs at the server's pace");
        }
        boolean headless = given.has("headless");
        int[] size = size(given.string("size"));
        List<String> files = given.all("screenshot");
        List<String> times = given.all("at");
        List<Shot> shots = new ArrayList<>();
        if (!times.isEmpty() && times.size() != files.size()) {
            throw new UsageException("give one --at per --screenshot: " + files.size() + " --screenshot and "
                    + times.size() + " --at");
        }
        for (int i = 0; i < files.size(); i++) {
            double at = times.isEmpty() ? 0 : seconds("at", times.get(i));
            shots.add(new Shot(at, Path.of(files.get(i))));
        }
        Double every = given.number("every", 1e-3, 1e6);
        Path out = given.has("out") ? Path.of(given.string("out")) : null;
        Double until = given.number("until", 0, 1e9);
        if (every != null && out == null) {
            throw new UsageException("--every needs --out DIR, the folder to write the screenshots to");
        }
        if (every == null && (out != null || until != null)) {
            throw new UsageException("--out and --until go with --every SECONDS");
        }
        if (every != null && !shots.isEmpty()) {
            throw new UsageException("give either --screenshot/--at or --every, not both");
        }
        Double measure = given.number("measure", 1, 3600);
        boolean shooting = !shots.isEmpty() || every != null;
        if (shooting && !headless) {
            throw new UsageException("--screenshot and --every need --headless");
        }
        if (headless && !shooting && measure == null) {
            throw new UsageException("--headless has nothing to do: give --screenshot FILE, --every SECONDS or "
                    + "--measure SECONDS");
        }
        if (shooting && measure != null) {
            throw new UsageException("--measure renders as fast as it can; take screenshots in another run");
        }
        Vec3 camera = point("camera", given.string("camera"));
        Vec3 lookAt = point("look-at", given.string("look-at"));
        if (!headless && (camera != null || lookAt != null)) {
            throw new UsageException("--camera and --look-at place the headless camera; in a window, move it "
                    + "with the mouse");
        }
        String follow = given.string("follow");
        if (follow != null && !follow.matches("[A-Za-z][A-Za-z0-9_-]{0,31}")) {
            throw new UsageException("--follow must be an agent's name (a letter, then up to 31 letters, digits, "
                    + "_ or -), was '" + follow + "'");
        }
        double lastTime = shots.stream().mapToDouble(Shot::time).max().orElse(0);
        if (until != null) {
            lastTime = until;
        }
        Double timeout = given.number("timeout", 1, 86_400);
        if (timeout == null) {
            timeout = BASE_TIMEOUT + (replay == null ? lastTime : 0) + (measure == null ? 0 : measure)
                    + (replay == null && every != null && until == null ? 600 : 0);
        }
        Integer port = given.integer("port", 1, 65535);
        return new ViewerOptions(given.string("host"), port, given.string("token"), replay,
                given.number("speed", ReplayState.MIN_SPEED, ReplayState.MAX_SPEED), headless, size[0], size[1],
                shots, every, out, until, camera, lookAt, follow, onOff(given, "hud"), onOff(given, "shadows"),
                timeout, measure);
    }

    /** Whether screenshots are to be taken. */
    public boolean shooting() {
        return !shots.isEmpty() || every != null;
    }

    private static int[] size(String text) throws UsageException {
        String[] parts = text.toLowerCase(java.util.Locale.ROOT).split("x");
        if (parts.length == 2) {
            try {
                int width = Integer.parseInt(parts[0].strip());
                int height = Integer.parseInt(parts[1].strip());
                if (width >= 64 && height >= 64 && width <= 8192 && height <= 8192) {
                    return new int[] {width, height};
                }
            } catch (NumberFormatException e) {
                // fall through to the message below
            }
        }
        throw new UsageException("--size must be WIDTHxHEIGHT in pixels, each 64 to 8192, such as 1280x720; was '"
                + text + "'");
    }

    private static double seconds(String option, String text) throws UsageException {
        try {
            double value = Double.parseDouble(text.strip());
            if (value >= 0 && value <= 1e9) {
                return value;
            }
        } catch (NumberFormatException e) {
            // fall through to the message below
        }
        throw new UsageException("--" + option + " must be a number of seconds, 0 or more, was '" + text + "'");
    }

    private static Vec3 point(String option, String text) throws UsageException {
        if (text == null) {
            return null;
        }
        String[] parts = text.split(",");
        if (parts.length == 3) {
            try {
                double x = Double.parseDouble(parts[0].strip());
                double y = Double.parseDouble(parts[1].strip());
                double z = Double.parseDouble(parts[2].strip());
                if (Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) {
                    return new Vec3(x, y, z);
                }
            } catch (NumberFormatException e) {
                // fall through to the message below
            }
        }
        throw new UsageException("--" + option + " must be three numbers X,Y,Z such as 10,25,40; was '" + text + "'");
    }

    private static boolean onOff(Options.Parsed given, String option) throws UsageException {
        return given.choice(option, "on", "off").equals("on");
    }
}
