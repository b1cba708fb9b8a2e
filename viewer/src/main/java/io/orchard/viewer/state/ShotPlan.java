package io.orchard.viewer.state;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * Which screenshots a headless run takes: a list of (time, file), or one every so many simulated
 * seconds into a folder, named after their time ({@code t0012.50.png}), until a given time or the
 * end of the game; a game that ends between two shots gets one more of its final state.
 */
public final class ShotPlan {

    private final List<Shot> fixed;
    private final double every;
    private final Path folder;
    private final double from;
    private final double until;
    private int taken;

    private ShotPlan(List<Shot> fixed, double every, Path folder, double from, double until) {
        this.fixed = fixed;
        this.every = every;
        this.folder = folder;
        this.from = from;
        this.until = until;
    }

    /** These shots, taken in the order of their times. */
    public static ShotPlan of(List<Shot> shots) {
        List<Shot> sorted = new ArrayList<>(shots);
        sorted.sort(Comparator.comparingDouble(Shot::time));
        return new ShotPlan(List.copyOf(sorted), 0, null, 0, 0);
    }

    /**
     * A shot every {@code every} simulated seconds from {@code from} up to and including
     * {@code until} (positive infinity: until the game ends), into {@code folder}.
     */
    public static ShotPlan every(double every, Path folder, double from, double until) {
        if (!(every > 0) || Double.isInfinite(every)) {
            throw new IllegalArgumentException("--every must be a positive number of seconds, was " + every);
        }
        return new ShotPlan(null, every, folder, from, until);
    }

    /** Whether this is a shot every so many seconds rather than a list. */
    public boolean isPeriodic() {
        return fixed == null;
    }

    /** The next shot to take, or null when all are taken. */
    public Shot next() {
        if (fixed != null) {
            return taken < fixed.size() ? fixed.get(taken) : null;
        }
        double time = from + taken * every;
        if (time > until + 1e-9) {
            return null;
        }
        return new Shot(time, folder.resolve(String.format(Locale.ROOT, "t%07.2f.png", time)));
    }

    /**
     * The shot of a live game's final state, when the game ends before the next periodic shot:
     * named after the time it ended, {@code t0012.50-final.png}, so that it sorts after the others.
     */
    Shot finalShot(double time) {
        if (fixed != null) {
            throw new IllegalStateException("a list of shots has no final shot");
        }
        return new Shot(time, folder.resolve(String.format(Locale.ROOT, "t%07.2f-final.png", time)));
    }

    /** Marks the next shot as taken. */
    void taken() {
        taken++;
    }

    /** How many shots were taken. */
    public int count() {
        return taken;
    }

    /** The time of the last shot, or NaN when it goes on until the game ends. */
    public double lastTime() {
        if (fixed != null) {
            return fixed.isEmpty() ? 0 : fixed.get(fixed.size() - 1).time();
        }
        return Double.isInfinite(until) ? Double.NaN : until;
    }
}
