package io.orchard.cluster.node;

import io.orchard.cluster.game.SplitGame;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.SimulationConfig;
import java.util.function.ObjLongConsumer;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thread that drives a split game's clock: in lockstep a tick ends when every agent's client
 * ended its turn or the deadline passed; in realtime ticks are due on a fixed wall-clock schedule.
 * While no tick passes it applies what clients send as it comes. After every tick it tells
 * {@code clock} the tick to come and the phase.
 */
final class SplitLoop implements Runnable {

    private static final Logger log = LoggerFactory.getLogger(SplitLoop.class);

    private final SplitGame game;
    private final SimulationConfig config;
    private final ObjLongConsumer<Phase> clock;
    private volatile boolean stopped;
    /** How long each tick took, in wall-clock nanoseconds, from its start to its end. */
    private final java.util.List<Long> ticks = new java.util.ArrayList<>();

    SplitLoop(SplitGame game, SimulationConfig config, ObjLongConsumer<Phase> clock) {
        this.game = game;
        this.config = config;
        this.clock = clock;
    }

    void stop() {
        stopped = true;
    }

    /** The tick time at this percentile so far, in milliseconds. */
    private String percentile(int percent) {
        java.util.List<Long> sorted = new java.util.ArrayList<>(ticks);
        sorted.sort(null);
        long nanos = sorted.isEmpty() ? 0 : sorted.get(Math.min(sorted.size() - 1, sorted.size() * percent / 100));
        return String.format(java.util.Locale.ROOT, "%.1f", nanos / 1e6);
    }

    @Override
    public void run() {
        long tickNanos = (long) (config.tickSeconds() * 1e9);
        long due = System.nanoTime();
        try {
            while (!stopped) {
                if (game.phase() != Phase.RUNNING) {
                    game.applyNow();
                    clock.accept(game.phase(), game.tick());
                    Thread.sleep(5);
                    due = System.nanoTime();
                    continue;
                }
                long started = System.nanoTime();
                game.beginTick();
                if (config.clock() == ClockMode.LOCKSTEP) {
                    game.awaitTurns(config.lockstepDeadline());
                } else {
                    due += tickNanos;
                    long left;
                    while (!stopped && (left = due - System.nanoTime()) > 0) {
                        LockSupport.parkNanos(left);
                    }
                }
                game.endTick();
                ticks.add(System.nanoTime() - started);
                clock.accept(game.phase(), game.tick());
                if (game.phase() == Phase.OVER) {
                    long[] sent = ClusterSerializer.sent();
                    log.info("the game is over at tick {}; across parcels' borders: {}; ticks p50 {} ms, p99 {} ms; "
                            + "the tick's node sent {} messages, {} bytes to other nodes", game.tick(), game.counts(),
                            percentile(50), percentile(99), sent[0], sent[1]);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException | Error e) {
            log.error("the split game failed at tick {}", game.tick(), e);
            throw e;
        }
    }
}
