package io.orchard.viewer.model.event;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.SceneNode;

/**
 * A running TimeSensor, the clock behind every animation in a VRML97 or X3D agent: while active
 * it sends {@code fraction_changed} (the position within the current cycle, 0 to 1),
 * {@code time}, {@code cycleTime} at each cycle start, and {@code isActive} when it starts and
 * stops.
 *
 * <p>It follows VRML97 with one addition: a sensor started explicitly ({@link #start}, as a move
 * or an animation request does) always delivers its final event, even when the first time step
 * after its start already lies past its end, so a late request still lands where it should.
 */
public final class LiveTimeSensor implements LiveNode {

    /**
     * Where the file's times lie on the viewer's clock. VRML counts time from 1970, so in a browser
     * a one-shot sensor with startTime 0 finished long before the page loaded, while the viewer's
     * clock starts at the game's start. Moving the file's times far into the past keeps their
     * meaning: one-shot sensors stay idle until started, looping ones are already running.
     */
    static final double FILE_TIME_ORIGIN = -1e9;

    private final String name;
    private double cycleInterval;
    private boolean enabled;
    private boolean loop;
    private double startTime;
    private double stopTime;
    private boolean active;
    private boolean explicitStart;
    private double cycleStart;

    /**
     * The sensor a TimeSensor node describes, in its initial state.
     *
     * @throws ModelException if its cycleInterval is not positive
     */
    public static LiveTimeSensor of(SceneNode node) throws ModelException {
        double interval = node.number("cycleInterval");
        if (!(interval > 0)) {
            throw new ModelException(Kind.BAD_VALUE, node.location() + ": " + node.label()
                    + " field cycleInterval must be positive but is " + interval);
        }
        return new LiveTimeSensor(node);
    }

    private LiveTimeSensor(SceneNode source) {
        this.name = source.defName().orElse(source.label());
        this.cycleInterval = source.number("cycleInterval");
        this.enabled = source.bool("enabled");
        this.loop = source.bool("loop");
        this.startTime = source.number("startTime") + FILE_TIME_ORIGIN;
        this.stopTime = source.number("stopTime") + FILE_TIME_ORIGIN;
    }

    @Override
    public String toString() {
        return "TimeSensor '" + name + "'";
    }

    /** The length of one cycle, in seconds. */
    public double cycleInterval() {
        return cycleInterval;
    }

    /**
     * Starts (or restarts) the sensor at {@code at}: enabled, with the given loop mode and
     * cycle interval, and no stop time.
     */
    public void start(double at, boolean looping, double interval) {
        this.enabled = true;
        this.loop = looping;
        this.cycleInterval = interval;
        this.startTime = at;
        this.stopTime = 0;
        this.active = false;
        this.explicitStart = true;
    }

    /** Stops the sensor by disabling it; the next step reports {@code isActive FALSE}. */
    public void stop() {
        this.enabled = false;
        this.explicitStart = false;
    }

    @Override
    public void receive(String field, Object value, EventGraph.Cascade cascade) {
        switch (field) {
            case "enabled" -> {
                enabled = (Boolean) value;
                if (!enabled && active) {
                    deactivate(cascade);
                }
            }
            case "loop" -> loop = (Boolean) value;
            case "cycleInterval" -> {
                double interval = (Double) value;
                if (!active && interval > 0) {
                    cycleInterval = interval;
                }
            }
            case "startTime" -> {
                if (!active) {
                    startTime = (Double) value;
                }
            }
            case "stopTime" -> {
                double stop = (Double) value;
                if (!active || stop > startTime) {
                    stopTime = stop;
                }
            }
            default -> {
                return;
            }
        }
        cascade.emit(this, field, value);
    }

    void tick(double now, EventGraph.Cascade cascade) {
        if (!enabled) {
            if (active) {
                deactivate(cascade);
            }
            return;
        }
        if (!active) {
            if (now < startTime) {
                return;
            }
            double end = end();
            if (now >= end) {
                if (explicitStart) {
                    explicitStart = false;
                    cascade.emit(this, "fraction_changed", endFraction(end));
                    cascade.emit(this, "time", now);
                }
                return;
            }
            active = true;
            explicitStart = false;
            cycleStart = startTime + Math.floor((now - startTime) / cycleInterval)
                    * cycleInterval;
            cascade.emit(this, "isActive", Boolean.TRUE);
            cascade.emit(this, "cycleTime", now);
        }
        double end = end();
        if (now >= end) {
            cascade.emit(this, "fraction_changed", endFraction(end));
            cascade.emit(this, "time", now);
            deactivate(cascade);
            return;
        }
        double cycle = startTime + Math.floor((now - startTime) / cycleInterval) * cycleInterval;
        if (cycle > cycleStart) {
            cycleStart = cycle;
            cascade.emit(this, "cycleTime", now);
        }
        cascade.emit(this, "fraction_changed", fractionAt(now));
        cascade.emit(this, "time", now);
    }

    /** When the sensor stops on its own: after one cycle unless looping, or at stopTime. */
    private double end() {
        double end = loop ? Double.POSITIVE_INFINITY : startTime + cycleInterval;
        if (stopTime > startTime) {
            end = Math.min(end, stopTime);
        }
        return end;
    }

    /** The last fraction: exactly 1 at the end of a cycle, else where stopTime cut it. */
    private double endFraction(double end) {
        boolean stoppedEarly = stopTime > startTime
                && (loop || stopTime < startTime + cycleInterval);
        return stoppedEarly && end == stopTime ? fractionAt(end) : 1.0;
    }

    private double fractionAt(double time) {
        double cycles = (time - startTime) / cycleInterval;
        double fraction = cycles - Math.floor(cycles);
        if (fraction == 0 && time > startTime) {
            fraction = 1.0;
        }
        return fraction;
    }

    private void deactivate(EventGraph.Cascade cascade) {
        active = false;
        cascade.emit(this, "isActive", Boolean.FALSE);
    }
}
