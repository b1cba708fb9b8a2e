package io.orchard.viewer;

import com.jme3.app.SimpleApplication;
import com.jme3.math.Vector3f;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.live.Backoff;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.replay.Recording;
import io.orchard.viewer.state.AgentsState;
import io.orchard.viewer.state.CameraState;
import io.orchard.viewer.state.HudState;
import io.orchard.viewer.state.InstructionState;
import io.orchard.viewer.state.KeysState;
import io.orchard.viewer.state.LiveState;
import io.orchard.viewer.state.MarkersState;
import io.orchard.viewer.state.MeasureState;
import io.orchard.viewer.state.ReplayState;
import io.orchard.viewer.state.RunControl;
import io.orchard.viewer.state.ScreenshotState;
import io.orchard.viewer.state.SelectionState;
import io.orchard.viewer.state.ShotPlan;
import io.orchard.viewer.state.SimClock;
import io.orchard.viewer.state.WorldSceneState;
import io.orchard.viewer.world.WorldMirror;
import java.io.PrintStream;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The viewer application: it only assembles app states, in the order they update each frame
 * (the source of messages and clock first, then screenshots, which may move a replay's clock, then
 * the world, the agents, the selection, the camera and the panels), and turns how the run ends
 * into an exit status. Any error jME reports ends the run with status 1, never 0, and no dialog.
 */
final class ViewerApp extends SimpleApplication implements RunControl {

    private static final Logger LOG = LoggerFactory.getLogger(ViewerApp.class);

    private final ViewerOptions options;
    private final Recording recording;
    private final PrintStream out;
    private final PrintStream err;
    private final CompletableFuture<Integer> exit = new CompletableFuture<>();
    private final CompletableFuture<Void> destroyed = new CompletableFuture<>();

    ViewerApp(ViewerOptions options, Recording recording, PrintStream out, PrintStream err) {
        super(new com.jme3.app.state.AppState[0]); // none of the default states: no fly cam, no stats
        this.options = options;
        this.recording = recording;
        this.out = out;
        this.err = err;
    }

    /** Completes with the exit status when the run ends. */
    CompletableFuture<Integer> exitStatus() {
        return exit;
    }

    /** Completes when the render thread has let go of the context. */
    CompletableFuture<Void> destroyedFuture() {
        return destroyed;
    }

    @Override
    public void simpleInitApp() {
        if (inputManager != null && inputManager.hasMapping(INPUT_MAPPING_EXIT)) {
            inputManager.deleteMapping(INPUT_MAPPING_EXIT); // Esc deselects; closing the window quits
        }
        WorldMirror mirror = new WorldMirror();
        SimClock clock;
        LiveState live = null;
        ReplayState replay = null;
        Supplier<String> source;
        if (recording != null) {
            boolean stepped = options.headless() && options.shooting();
            replay = new ReplayState(recording, mirror, options.speed(), stepped);
            stateManager.attach(replay);
            clock = replay;
            ReplayState playing = replay;
            String file = recording.file().getFileName().toString();
            source = () -> String.format(Locale.ROOT, "replay %s  x%s%s%s", file, speed(playing.speed()),
                    playing.isPaused() ? "  paused" : "", playing.now() >= playing.endTime() ? "  (end)" : "");
        } else {
            live = new LiveState(options.host(), options.port(), options.token(), options.operatorToken(),
                    options.reconnect() ? Backoff.DEFAULT : null, mirror, this);
            stateManager.attach(live);
            clock = live;
            source = live::status;
        }
        if (options.shooting()) {
            ShotPlan plan = options.every() == null ? ShotPlan.of(options.shots())
                    : ShotPlan.every(options.every(), options.out(), recording == null ? 0 : recording.startTime(),
                    options.until() != null ? options.until()
                            : recording != null ? recording.endTime() : Double.POSITIVE_INFINITY);
            stateManager.attach(new ScreenshotState(plan, mirror, clock, replay, this));
        }
        stateManager.attach(new WorldSceneState(mirror, options.shadows()));
        stateManager.attach(new AgentsState(mirror, clock, ModelLimits.DEFAULTS));
        stateManager.attach(new MarkersState(mirror, clock));
        SelectionState selection = new SelectionState(mirror, clock);
        stateManager.attach(selection);
        stateManager.attach(new CameraState(mirror, clock, !options.headless(), vector(options.camera()),
                vector(options.lookAt())));
        if (options.hud()) {
            stateManager.attach(new HudState(mirror, clock, source, !options.headless()));
        }
        if (!options.headless()) {
            stateManager.attach(new InstructionState(live));
            stateManager.attach(new KeysState());
        }
        if (options.measure() != null) {
            stateManager.attach(new MeasureState(options.measure(), mirror, this, String.format(Locale.ROOT,
                    "%dx%d, shadows %s", options.width(), options.height(), options.shadows() ? "on" : "off")));
        }
        if (options.follow() != null) {
            selection.select(options.follow());
        }
    }

    private static String speed(double speed) {
        return speed >= 1 ? String.format(Locale.ROOT, "%.0f", speed) : String.format(Locale.ROOT, "1/%.0f", 1 / speed);
    }

    private static Vector3f vector(Vec3 v) {
        return v == null ? null : new Vector3f((float) v.x(), (float) v.y(), (float) v.z());
    }

    @Override
    public boolean headless() {
        return options.headless();
    }

    @Override
    public void finished(String summary) {
        if (exit.complete(0)) {
            LOG.info("done: {}", summary);
            if (context != null) {
                stop();
            }
        }
    }

    @Override
    public void failed(String reason) {
        if (exit.complete(1)) {
            err.println("orchard viewer: " + reason);
            if (context != null) {
                stop();
            }
        }
    }

    @Override
    public void report(String line) {
        out.println(line);
    }

    /**
     * jME's own error handling logs and exits with status 0 (and may open a dialog); here every
     * error ends the run with status 1 and says why.
     */
    @Override
    public void handleError(String message, Throwable cause) {
        LOG.error("{}", message, cause);
        String why = cause == null || cause.getMessage() == null || message.contains(cause.getMessage()) ? message
                : message + ": " + cause.getMessage();
        if (exit.complete(1)) {
            err.println("orchard viewer: render failed: " + why);
        }
        if (context != null) {
            stop();
        }
    }

    @Override
    public void destroy() {
        try {
            super.destroy();
        } finally {
            exit.complete(0); // the window was closed
            destroyed.complete(null);
        }
    }
}
