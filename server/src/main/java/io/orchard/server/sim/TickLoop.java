package io.orchard.server.sim;

import io.orchard.protocol.message.EndTurnMessage;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thread that owns the simulation and drives its clock. In realtime mode ticks are due on a
 * fixed wall-clock schedule (20 a second by default) and what arrives late waits for the next; in
 * lockstep mode a tick ends as soon as every client that drives an agent has ended its turn (at
 * once when there is none), or when the deadline passes ({@link SimulationConfig#lockstepDeadline()}; a client that misses it
 * several times in a row is no longer waited for, see {@link Turns}). While no game runs it applies
 * what clients send as it comes; a lockstep game whose agents have come starts when their setup
 * turns are over, or when the deadline passes. It measures how long each tick works
 * ({@link #stats()}). Its time is a {@link LoopClock}, the system's in a server, so that tests step
 * it without waiting.
 */
public final class TickLoop implements Runnable {

    private static final Logger log = LoggerFactory.getLogger(TickLoop.class);

    /** How far behind its schedule a realtime clock may fall before it gives up catching up. */
    private static final int MAX_BEHIND_TICKS = 3;

    private final Simulation sim;
    private final LoopClock clock;
    private final TickTimes times = new TickTimes();
    private volatile boolean stopped;
    /** When the next realtime tick is due (on the clock); reset when ticks start passing again. */
    private long due;
    private boolean wasRunning;
    /** When a due lockstep start stops waiting for setup turns (on the clock); -1 when none is due. */
    private long startDeadline = -1;

    /** A loop on the system's clock. */
    public TickLoop(Simulation sim) {
        this(sim, LoopClock.SYSTEM);
    }

    TickLoop(Simulation sim, LoopClock clock) {
        this.sim = sim;
        this.clock = clock;
    }

    /** Asks the loop to end after the current step; the thread then returns from {@link #run()}. */
    public void stop() {
        stopped = true;
    }

    /** How long the ticks took so far. Safe from any thread. */
    public TickStats stats() {
        return times.stats();
    }

    /** Forgets the ticks measured so far. Safe from any thread. */
    public void resetStats() {
        times.reset();
    }

    @Override
    public void run() {
        try {
            while (!stopped) {
                step();
            }
            sim.flushWaiting();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException | Error e) {
            log.error("the simulation failed at tick {}", sim.tick(), e);
            throw e;
        }
    }

    /** One tick while the game runs; otherwise what clients sent, or a short wait for it. */
    void step() throws InterruptedException {
        if (sim.phase() == Phase.RUNNING) {
            if (!wasRunning) {
                due = clock.nanoTime();
                wasRunning = true;
            }
            tick();
        } else {
            wasRunning = false;
            sim.flushWaiting();
            idle();
        }
    }

    private void idle() throws InterruptedException {
        long wait = 50;
        if (sim.startDue()) {
            long now = clock.nanoTime();
            if (startDeadline < 0) {
                startDeadline = now + sim.config().lockstepDeadline().toNanos();
            }
            long left = startDeadline - now;
            if (left <= 0) {
                startDeadline = -1;
                sim.startWithoutSetup();
                return;
            }
            wait = Math.min(wait, Math.max(1, left / 1_000_000));
        } else {
            startDeadline = -1;
        }
        Event first = sim.poll(clock, wait);
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
        long started = clock.nanoTime();
        boolean late = started - due > tickNanos();
        sim.beginTick();
        long work = clock.nanoTime() - started;
        List<Event> events = new ArrayList<>();
        if (sim.lockstep()) {
            collectUntilTurnsEnd(tick, events);
        } else {
            // Ticks are due on a fixed schedule, so the rate holds however long each tick worked; a
            // clock that fell far behind (a long pause, an overload) starts a new schedule instead
            // of rushing through the ticks it missed.
            due += tickNanos();
            long now = clock.nanoTime();
            if (now - due > MAX_BEHIND_TICKS * tickNanos()) {
                due = now;
            }
            // What clients send only counts at the end of the tick: sleep until then, then take it all.
            long left;
            while (!stopped && (left = due - clock.nanoTime()) > 0) {
                clock.sleep(left);
            }
        }
        sim.drain(events);
        long ending = clock.nanoTime();
        // The next tick begins at once in either mode (once due, in realtime): what the end of this
        // one sends goes out with its start, in one write per client, for one wake-up instead of two.
        sim.endTick(events, true);
        work += clock.nanoTime() - ending;
        times.record(work, late);
    }

    private long tickNanos() {
        return (long) (sim.config().tickSeconds() * 1e9);
    }

    private void collectUntilTurnsEnd(long tick, List<Event> events) throws InterruptedException {
        long deadline = clock.nanoTime() + sim.config().lockstepDeadline().toNanos();
        // Who drives an agent cannot change before the end of the tick (registrations take effect
        // then), except by leaving. Late clients are not waited for.
        Set<Long> waiting = new HashSet<>(sim.turnsToWaitFor());
        // No agent's client to wait for (its agents' clients have all left): every turn is over at
        // once, and the tick with it; the game runs on to its end, or to a command that changes it.
        while (!stopped) {
            if (waiting.isEmpty()) {
                return;
            }
            long left = deadline - clock.nanoTime();
            if (left <= 0) {
                return;
            }
            Event event = sim.poll(clock, Math.max(1, left / 1_000_000));
            if (event == null) {
                continue;
            }
            events.add(event);
            if (event instanceof Event.Received received && received.message() instanceof EndTurnMessage end
                    && end.tick() >= tick) {
                waiting.remove(received.session().id());
            } else if (event instanceof Event.Disconnected) {
                // A client that left has nothing more to say in this tick.
                waiting.remove(event.session().id());
            }
        }
    }
}
