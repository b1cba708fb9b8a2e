package io.orchard.viewer;

import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import io.orchard.cli.CommandLineErrors;
import io.orchard.viewer.replay.Recording;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.logging.Level;
import picocli.CommandLine;

/**
 * The viewer's command line: {@code ./orchard viewer [options]} (or this class as the main class).
 * It watches a live server ({@code --host}, {@code --port}) or replays a recording
 * ({@code --replay FILE}), in a window, or headless ({@code --headless}) writing screenshots at
 * given simulated times ({@code --screenshot FILE --at SECONDS}, or {@code --every SECONDS --out
 * DIR}) or measuring the frame rate ({@code --measure SECONDS}), and then exits.
 *
 * <p>Headless rendering still needs an X display and OpenGL, such as Xvfb with Mesa:
 * {@code xvfb-run -a -s "-screen 0 1280x720x24" ./orchard viewer --headless ...}. A watchdog
 * ({@code --timeout}) bounds every headless run. Exit status: 0 done, 1 failed, 2 bad command line.
 * {@link #command} hands the command line to a launcher as its subcommand {@code viewer}.
 */
public final class ViewerMain {

    // Held so that the logger's level is not lost when the logger is garbage-collected.
    private static final java.util.logging.Logger JME_LOG = java.util.logging.Logger.getLogger("com.jme3");

    private ViewerMain() {
    }

    /** Runs the viewer with the command line {@code args} and exits with its status. */
    public static void main(String[] args) {
        int status = run(Arrays.asList(args), System.out, System.err);
        System.out.flush();
        System.exit(status);
    }

    /** The help text of the viewer's command line. */
    public static String help() {
        return command(System.out, System.err).setCommandName("orchard viewer")
                .getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    /**
     * Runs the viewer as {@code orchard viewer} until it is done (headless) or its window is
     * closed, and returns the exit status. The caller should exit the JVM afterwards: a stuck
     * graphics driver may leave a thread behind after a watchdog timeout.
     */
    public static int run(List<String> args, PrintStream out, PrintStream err) {
        return CommandLineErrors.execute(command(out, err).setCommandName("orchard viewer"), args, err);
    }

    /**
     * The viewer's command line as a picocli command named {@code viewer}, for a launcher to add as
     * its subcommand; it prints to {@code out} and {@code err}.
     */
    public static CommandLine command(PrintStream out, PrintStream err) {
        return new CommandLine(new ViewerCommand(out, err)).setOut(new PrintWriter(out, true))
                .setErr(new PrintWriter(err, true));
    }

    /** Shows the world as the options say; returns the exit status. */
    static int show(ViewerOptions options, PrintStream out, PrintStream err) {
        Recording recording = null;
        if (options.replay() != null) {
            try {
                recording = Recording.read(options.replay());
            } catch (IOException e) {
                err.println("orchard viewer: " + e.getMessage());
                return 1;
            }
        }
        String display = missingDisplay(options.headless());
        if (display != null) {
            err.println("orchard viewer: " + display);
            return 1;
        }
        JulToSlf4j.install();
        JME_LOG.setLevel(Level.WARNING);
        ViewerApp app = new ViewerApp(options, recording, out, err);
        app.setSettings(settings(options));
        app.setShowSettings(false);
        app.setPauseOnLostFocus(false);
        app.start(options.headless() ? JmeContext.Type.OffscreenSurface : JmeContext.Type.Display, false);
        int status;
        try {
            status = options.headless() ? app.exitStatus().get((long) (options.timeout() * 1000), TimeUnit.MILLISECONDS)
                    : app.exitStatus().get();
        } catch (TimeoutException e) {
            err.println(String.format(Locale.ROOT, "orchard viewer: watchdog: the headless run did not finish within "
                    + "%.0f s (raise --timeout for long runs)", options.timeout()));
            status = 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            status = 1;
        } catch (ExecutionException e) {
            err.println("orchard viewer: " + e.getCause());
            status = 1;
        }
        app.stop();
        try {
            app.destroyedFuture().get(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | TimeoutException e) {
            err.println("orchard viewer: the renderer did not shut down within 10 s");
            status = status == 0 ? 1 : status;
        }
        return status;
    }

    private static AppSettings settings(ViewerOptions options) {
        AppSettings settings = new AppSettings(true);
        settings.setTitle("Orchard viewer");
        settings.setResolution(options.width(), options.height());
        settings.setWindowSize(options.width(), options.height());
        settings.setAudioRenderer(null);
        settings.putString("AssetConfigURL", "io/orchard/viewer/assets.cfg");
        // Without a Wayland session GLFW would try Wayland first all the same, and libwayland then
        // complains on standard error that XDG_RUNTIME_DIR is invalid (as under xvfb-run).
        settings.setX11PlatformPreferred(System.getenv("WAYLAND_DISPLAY") == null);
        settings.setUseJoysticks(false);
        settings.setGammaCorrection(true);
        settings.setSamples(0);
        settings.setVSync(!options.headless());
        settings.setFrameRate(options.headless() ? -1 : 60);
        settings.setResizable(!options.headless());
        return settings;
    }

    /** Why no OpenGL context can be made here, or null when a display is available. */
    private static String missingDisplay(boolean headless) {
        boolean linux = System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("linux");
        if (!linux || System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null) {
            return null;
        }
        return headless
                ? "no X display (DISPLAY is not set): headless rendering still needs one; run under Xvfb, e.g. "
                        + "xvfb-run -a -s \"-screen 0 1280x720x24\" ./orchard viewer --headless ... (Debian: "
                        + "apt-get install xvfb xauth)"
                : "no display (DISPLAY is not set): run it on a desktop, or use --headless under xvfb-run";
    }
}
