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

    SplitLoop(SplitGame game, SimulationConfig config, ObjLongConsumer<Phase> clock) {
        this.game = game;
        this.config = config;
        this.clock = clock;
    }

    void stop() {
        stopped = true;
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
                clock.accept(game.phase(), game.tick());
                if (game.phase() == Phase.OVER) {
                    log.info("the game is over at tick {}; across parcels' borders: {}", game.tick(), game.counts());
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
