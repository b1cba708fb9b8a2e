package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.renderer.Statistics;
import com.jme3.app.state.BaseAppState;
import io.orchard.viewer.world.WorldMirror;
import java.util.Locale;

/**
 * Measures the frame rate: once the world is shown and every model is in place, it lets one
 * second pass to warm up, then counts frames for the given wall-clock time and reports frames per
 * second, and the run finishes.
 */
public final class MeasureState extends BaseAppState {

    private static final double WARM_UP = 1.0;

    private final double seconds;
    private final WorldMirror mirror;
    private final RunControl control;
    private final String setting;
    private long started;
    private long frames;
    private long drawCalls;
    private boolean done;

    /**
     * Counts the frames of {@code seconds} of wall clock once the world of {@code mirror} is shown, then
     * reports the rate and ends the run through {@code control}.
     *
     * @param setting what is measured, for the report (size, shadows)
     */
    public MeasureState(double seconds, WorldMirror mirror, RunControl control, String setting) {
        this.seconds = seconds;
        this.mirror = mirror;
        this.control = control;
        this.setting = setting;
    }

    @Override
    public void update(float tpf) {
        if (done) {
            return;
        }
        AgentsState agents = getState(AgentsState.class);
        if (started == 0) {
            if (mirror.hasWorld() && (agents == null || agents.isSettled())) {
                started = System.nanoTime() + (long) (WARM_UP * 1e9);
            }
            return;
        }
        long now = System.nanoTime();
        if (now < started) {
            return;
        }
        frames++;
        drawCalls += lastFrameDrawCalls();
        double elapsed = (now - started) / 1e9;
        if (elapsed >= seconds) {
            done = true;
            String line = String.format(Locale.ROOT, "%.1f frames per second (%d frames in %.1f s; %s; %d agents;"
                    + " %d draw calls a frame)", frames / elapsed, frames, elapsed, setting, mirror.agents().size(),
                    drawCalls / frames);
            control.report(line);
            control.finished(line);
        }
    }

    /** The geometries the last frame drew, one draw call each. */
    private long lastFrameDrawCalls() {
        Statistics statistics = getApplication().getRenderer().getStatistics();
        String[] labels = statistics.getLabels();
        int[] data = new int[labels.length];
        statistics.getData(data);
        for (int i = 0; i < labels.length; i++) {
            if (labels[i].equals("Objects")) {
                return data[i];
            }
        }
        return 0;
    }

    @Override
    protected void initialize(Application app) {
        app.getRenderer().getStatistics().setEnabled(true);
    }

    @Override
    protected void cleanup(Application app) {
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
