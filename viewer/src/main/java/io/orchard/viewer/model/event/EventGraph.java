package io.orchard.viewer.model.event;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Set;

/**
 * The VRML97 execution model, reduced to what agent models use: at each time step every
 * TimeSensor produces its events, and each event travels along the ROUTEs from its field,
 * possibly causing further events, until none are left. As in VRML97, one field sends at most
 * one event per time step, which is what ends loops of ROUTEs. The cascade is a queue, not
 * recursion, so long chains cannot overflow the stack.
 *
 * <p>Not thread-safe: one thread (the render thread) steps it.
 */
public final class EventGraph {

    private record Source(LiveNode node, String field) {
    }

    private record Target(LiveNode node, String field) {
    }

    private record Event(LiveNode from, String field, Object value) {
    }

    private final Map<Source, List<Target>> routes = new HashMap<>();
    private final List<LiveTimeSensor> sensors = new ArrayList<>();

    /** Adds a TimeSensor, which will produce events at each step. */
    public void addSensor(LiveTimeSensor sensor) {
        sensors.add(sensor);
    }

    /** Adds a ROUTE: events {@code from} sends on {@code fromField} reach {@code toField} of {@code to}. */
    public void addRoute(LiveNode from, String fromField, LiveNode to, String toField) {
        routes.computeIfAbsent(new Source(from, fromField), s -> new ArrayList<>())
                .add(new Target(to, toField));
    }

    /** Whether any ROUTE leads from {@code from.fromField} to {@code to.toField}. */
    public boolean isRouted(LiveNode from, String fromField, LiveNode to, String toField) {
        return routes.getOrDefault(new Source(from, fromField), List.of())
                .contains(new Target(to, toField));
    }

    /** Runs one time step at simulated time {@code now}, in seconds. */
    public void step(double now) {
        Cascade cascade = new Cascade(now);
        for (LiveTimeSensor sensor : sensors) {
            sensor.tick(now, cascade);
        }
        cascade.drain();
    }

    /** The events of one time step. */
    public final class Cascade {

        private final double now;
        private final Queue<Event> pending = new ArrayDeque<>();
        private final Set<Source> fired = new HashSet<>();

        private Cascade(double now) {
            this.now = now;
        }

        /** The time stamp of this step. */
        double now() {
            return now;
        }

        /** Sends an event from {@code from.field}, unless that field already sent one. */
        void emit(LiveNode from, String field, Object value) {
            if (fired.add(new Source(from, field))) {
                pending.add(new Event(from, field, value));
            }
        }

        private void drain() {
            Event event;
            while ((event = pending.poll()) != null) {
                for (Target target : routes.getOrDefault(new Source(event.from(), event.field()),
                        List.of())) {
                    target.node().receive(target.field(), event.value(), this);
                }
            }
        }
    }
}
