package io.orchard.cluster.node;

import io.orchard.cluster.game.ParcelLost;
import io.orchard.cluster.game.SplitGame;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.SimulationConfig;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import java.util.function.ObjLongConsumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thread that drives a split game's clock, as the single server's tick loop drives its
 * simulation: in lockstep a tick ends when every agent's client ended its turn (but the late ones)
 * or the deadline passed, and a game whose agents have come starts when their setup turns are over,
 * or the deadline passed; in realtime ticks are due on a fixed wall-clock schedule. While no tick
 * passes it applies what clients send as it comes. After every step it tells {@code clock} the tick
 * to come and the phase.
 */
final class SplitLoop implements Runnable {

    private static final Logger log = LoggerFactory.getLogger(SplitLoop.class);

    /** How far behind its schedule a realtime clock may fall before it gives up catching up. */
    private static final int MAX_BEHIND_TICKS = 3;

    /** The game the loop drives, which a rollback replaces. */
    interface Games {
        /** The game to drive now. */
        SplitGame current();

        /** A step failed: a parcel did not answer. */
        void failed(ParcelLost lost) throws InterruptedException;

        /** Between two steps: where a rollback replaces the game. */
        void between() throws InterruptedException;
    }

    private final Games games;
    private final ObjLongConsumer<Phase> clock;
    private volatile boolean stopped;
    /** How long each tick took, in wall-clock nanoseconds, from its start to its end. */
    private final List<Long> ticks = new ArrayList<>();
    /**
     * How long each tick's own work took: the tick without the wait for the agents' turns (lockstep)
     * or for the next tick's time (realtime), what the cluster costs a tick.
     */
    private final List<Long> work = new ArrayList<>();

    SplitLoop(Games games, ObjLongConsumer<Phase> clock) {
        this.games = games;
        this.clock = clock;
    }

    void stop() {
        stopped = true;
    }

    /** The time of {@code times} at this percentile so far, in milliseconds. */
    private static String percentile(List<Long> times, int percent) {
        List<Long> sorted = new ArrayList<>(times);
        sorted.sort(null);
        long nanos = sorted.isEmpty() ? 0 : sorted.get(Math.min(sorted.size() - 1, sorted.size() * percent / 100));
        return String.format(Locale.ROOT, "%.1f", nanos / 1e6);
    }

    @Override
    public void run() {
        try {
            while (!stopped) {
                try {
                    step(games.current());
                } catch (ParcelLost lost) {
                    games.failed(lost);
                }
                games.between();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException | Error e) {
            log.error("the split game failed at tick {}", games.current().tick(), e);
            throw e;
        }
    }

    private long due = System.nanoTime();
    private long startDeadline = -1;
    private boolean wasOver;
    private SplitGame last;

    /** One tick while the game runs; otherwise what clients sent, or a short wait for it. */
    private void step(SplitGame game) throws InterruptedException {
        if (game != last) { // a new game, or one rolled back
            last = game;
            wasOver = false;
            startDeadline = -1;
        }
        SimulationConfig config = game.config();
        long tickNanos = (long) (config.tickSeconds() * 1e9);
        if (game.phase() != Phase.RUNNING) {
            long wait = 50;
            if (game.startDue()) {
                long now = System.nanoTime();
                startDeadline = startDeadline < 0 ? now + config.lockstepDeadline().toNanos() : startDeadline;
                if (now >= startDeadline) {
                    startDeadline = -1;
                    game.startWithoutSetup();
                }
                wait = Math.max(1, Math.min(wait, (startDeadline - now) / 1_000_000));
            } else {
                startDeadline = -1;
            }
            game.applyNext(wait);
            clock.accept(game.phase(), game.tick());
            due = System.nanoTime();
            return;
        }
        long started = System.nanoTime();
        game.beginTick();
        long begun = System.nanoTime();
        if (config.clock() == ClockMode.LOCKSTEP) {
            game.awaitTurns(config.lockstepDeadline());
        } else {
            due += tickNanos;
            if (System.nanoTime() - due > MAX_BEHIND_TICKS * tickNanos) {
                due = System.nanoTime();
            }
            long left;
            while (!stopped && (left = due - System.nanoTime()) > 0) {
                LockSupport.parkNanos(left);
            }
        }
        long ending = System.nanoTime();
        game.endTick();
        long ended = System.nanoTime();
        ticks.add(ended - started);
        work.add(begun - started + ended - ending);
        clock.accept(game.phase(), game.tick());
        if (game.phase() == Phase.OVER && !wasOver) {
            wasOver = true;
            long[] sent = ClusterSerializer.sent();
            log.info("the game is over at tick {}; across parcels' borders: {}; ticks p50 {} ms, p99 {} ms; "
                    + "tick work p50 {} ms, p99 {} ms; the tick's node sent {} messages, {} bytes to other nodes ({})",
                    game.tick(), game.counts(), percentile(ticks, 50), percentile(ticks, 99), percentile(work, 50),
                    percentile(work, 99), sent[0], sent[1], ClusterSerializer.sentByKind());
        }
    }
}
