package io.orchard.server.sim;

import io.orchard.protocol.message.EndTurnMessage;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thread that owns the simulation and drives its clock. In realtime mode a tick lasts its
 * share of a wall-clock second and what arrives late waits for the next; in lockstep mode a tick
 * ends as soon as every client that drives an agent has ended its turn, or when the deadline passes.
 * While no game runs it applies what clients send as it comes.
 */
public final class TickLoop implements Runnable {

    private static final Logger log = LoggerFactory.getLogger(TickLoop.class);

    private final Simulation sim;
    private volatile boolean stopped;

    public TickLoop(Simulation sim) {
        this.sim = sim;
    }

    /** Asks the loop to end after the current step; the thread then returns from {@link #run()}. */
    public void stop() {
        stopped = true;
    }

    @Override
    public void run() {
        try {
            while (!stopped) {
                if (sim.phase() == Phase.RUNNING) {
                    tick();
                } else {
                    idle();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException | Error e) {
            log.error("the simulation failed at tick {}", sim.tick(), e);
            throw e;
        }
    }

    private void idle() throws InterruptedException {
        Event first = sim.poll(50);
        List<Event> events = new ArrayList<>();
        if (first != null) {
            events.add(first);
        }
        sim.drain(events);
        if (!events.isEmpty()) {
            sim.applyBuffered(events);
        }
    }

    private void tick() throws InterruptedException {
        long tick = sim.tick();
        sim.beginTick();
        List<Event> events = new ArrayList<>();
        if (sim.lockstep()) {
            collectUntilTurnsEnd(tick, events);
        } else {
            long end = System.nanoTime() + (long) (sim.config().tickSeconds() * 1e9);
            long left;
            while (!stopped && (left = end - System.nanoTime()) > 0) {
                Event event = sim.poll(Math.max(1, left / 1_000_000));
                if (event != null) {
                    events.add(event);
                }
            }
        }
        sim.drain(events);
        sim.endTick(events);
    }

    private void collectUntilTurnsEnd(long tick, List<Event> events) throws InterruptedException {
        long deadline = System.nanoTime() + sim.config().lockstepDeadline().toNanos();
        Set<Long> ended = new HashSet<>();
        while (!stopped) {
            if (ended.containsAll(sim.agentSessions()) && !sim.agentSessions().isEmpty()) {
                return;
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return;
            }
            Event event = sim.poll(Math.max(1, left / 1_000_000));
            if (event == null) {
                continue;
            }
            events.add(event);
            if (event instanceof Event.Received received && received.message() instanceof EndTurnMessage end
                    && end.tick() >= tick) {
                ended.add(received.session().id());
            } else if (event instanceof Event.Disconnected) {
                // A client that left has nothing more to say in this tick.
                ended.add(event.session().id());
            }
        }
    }
}
