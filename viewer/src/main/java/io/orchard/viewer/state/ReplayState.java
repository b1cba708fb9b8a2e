package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import io.orchard.viewer.replay.Recording;
import io.orchard.viewer.world.WorldMirror;
import java.util.List;

/**
 * Plays a {@link Recording} into the {@link WorldMirror}, and is the scene's clock while it does:
 * the clock follows the recording's simulated time, advanced each frame by the frame's duration
 * times the speed, or (for headless screenshots) moved only by {@link #advanceTo}, so that the same
 * recording always gives the same frames. Seeking back replays the recording from its start up to
 * the target, which rebuilds the scene.
 */
public final class ReplayState extends BaseAppState implements SimClock {

    /** The slowest and fastest speeds {@link #setSpeed} accepts. */
    public static final double MIN_SPEED = 1.0 / 16;
    /** The fastest speed {@link #setSpeed} accepts. */
    public static final double MAX_SPEED = 64;

    private final Recording recording;
    private final List<Recording.Entry> entries;
    private final WorldMirror mirror;
    private final boolean stepped;
    private double speed;
    private boolean paused;
    private int next;
    private double now;

    /**
     * Plays {@code recording} into {@code mirror} at {@code speed}.
     *
     * @param stepped true when only {@link #advanceTo} moves the clock (headless screenshots)
     */
    public ReplayState(Recording recording, WorldMirror mirror, double speed, boolean stepped) {
        this.recording = recording;
        this.entries = recording.entries();
        this.mirror = mirror;
        this.stepped = stepped;
        setSpeed(speed);
    }

    @Override
    protected void initialize(Application app) {
        now = recording.startTime();
        advanceTo(now);
    }

    @Override
    public void update(float tpf) {
        if (!stepped && !paused) {
            advanceTo(now + tpf * speed);
        }
    }

    /** Applies every message recorded up to {@code time} and shows that time; earlier times are ignored. */
    public void advanceTo(double time) {
        while (next < entries.size() && entries.get(next).time() <= time) {
            Recording.Entry entry = entries.get(next++);
            mirror.apply(entry.message(), entry.time());
        }
        now = Math.max(now, time);
    }

    /** Shows the game at {@code time}: forward by playing on, backward by replaying from the start. */
    public void seek(double time) {
        double target = Math.max(recording.startTime(), time);
        if (target < now) {
            mirror.clear();
            next = 0;
            now = recording.startTime();
        }
        advanceTo(target);
    }

    @Override
    public double now() {
        return now;
    }

    /** The recording's simulated time at its start. */
    public double startTime() {
        return recording.startTime();
    }

    /** The recording's simulated time at its last message. */
    public double endTime() {
        return recording.endTime();
    }

    /** Whether every message has been played. */
    public boolean atEnd() {
        return next >= entries.size();
    }

    /** The recording played. */
    public Recording recording() {
        return recording;
    }

    /** Whether the replay is paused. */
    public boolean isPaused() {
        return paused;
    }

    /** Pauses the replay, or lets it go on. */
    public void setPaused(boolean paused) {
        this.paused = paused;
    }

    /** The speed of the replay: simulated seconds per second of wall clock. */
    public double speed() {
        return speed;
    }

    /**
     * Sets how many simulated seconds pass per second of wall-clock time.
     *
     * @throws IllegalArgumentException when it is outside [{@value #MIN_SPEED}, {@value #MAX_SPEED}]
     */
    public void setSpeed(double speed) {
        if (!(speed >= MIN_SPEED && speed <= MAX_SPEED)) {
            throw new IllegalArgumentException("replay speed must be " + MIN_SPEED + " to " + MAX_SPEED + ", was " + speed);
        }
        this.speed = speed;
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
