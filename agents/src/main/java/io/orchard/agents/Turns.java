package io.orchard.agents;

import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Nullable;

/**
 * The clock as the agent lives it: the current tick, its time, and the agent's turn in it. A turn
 * opens with a {@code Tick} once the agent is in the world, and is taken on that tick's
 * perception, whose three parts are gathered here as they arrive; or without one, when none is due
 * ({@link PerceptionSchedule}) or it did not come in time ({@link #waitMillis()}). In lockstep
 * mode the server waits for every agent to end its turn, so a taken turn ends with an
 * {@code EndTurn}.
 */
final class Turns {

    private final Session session;
    private final PerceptionSchedule schedule = new PerceptionSchedule();
    private boolean lockstep;
    private int tickRate = 1;
    private long tick = -1;
    private double time;
    private boolean open;
    private boolean deciding;
    private PerceptionMessage pendingPerception;
    private LandmarkPerceptionMessage pendingLandmarks;

    Turns(Session session) {
        this.session = session;
    }

    /** The server's clock: lockstep or real time, and its ticks a second. */
    void welcomed(WelcomeMessage welcome) {
        lockstep = welcome.clock() == ClockMode.LOCKSTEP;
        tickRate = welcome.tickRate();
    }

    /** The current tick; -1 before the first. */
    long tick() {
        return tick;
    }

    /** Simulated seconds at the start of the current tick. */
    double time() {
        return time;
    }

    /** Whether the server's clock is lockstep. */
    boolean lockstep() {
        return lockstep;
    }

    /** Ticks a second, as the server welcomed the agent. */
    int tickRate() {
        return tickRate;
    }

    /** Whether this tick's turn waits to be taken. */
    boolean open() {
        return open;
    }

    /**
     * A tick began; its turn opens if the agent is in the world.
     *
     * @return whether to take the turn at once, as no perception is due in this tick
     */
    boolean began(TickMessage begun, boolean inWorld) {
        tick = begun.tick();
        time = begun.time();
        if (!inWorld) {
            return false;
        }
        open = true;
        if (pendingPerception != null && pendingPerception.tick() < tick) {
            pendingPerception = null;
            pendingLandmarks = null;
        }
        PerceptionSchedule.Expect expect = schedule.expect(tick);
        // In lockstep, waiting a while for a perception that may come would let the wall clock decide.
        return expect == PerceptionSchedule.Expect.NO || (expect == PerceptionSchedule.Expect.MAYBE && lockstep);
    }

    /** The first part of a perception came. */
    void perceived(PerceptionMessage seen) {
        pendingPerception = seen;
        pendingLandmarks = null;
    }

    /** The landmark part of a perception came. */
    void perceived(LandmarkPerceptionMessage landmarks) {
        pendingLandmarks = landmarks;
    }

    /** The castle part, the last, completes a perception; null when its first part did not come. */
    @Nullable Perception completed(CastlePerceptionMessage castle) {
        PerceptionMessage seen = pendingPerception;
        if (seen == null || seen.tick() != castle.tick()) {
            return null;
        }
        Perception perception = new Perception(seen, pendingLandmarks, castle);
        pendingPerception = null;
        pendingLandmarks = null;
        schedule.perceived(seen.tick());
        return perception;
    }

    /** Whether the open turn waits for this perception. */
    boolean awaits(Perception perception) {
        return open && perception.tick() == tick;
    }

    /** The turn is taken: the agent decides now. */
    void take() {
        open = false;
        deciding = true;
    }

    /** The agent has decided; in lockstep mode its turn ends. */
    void taken() {
        deciding = false;
        if (lockstep) {
            long ended = tick;
            session.send(s -> new EndTurnMessage(s, ended));
        }
    }

    /**
     * The agent registered: in lockstep mode its setup turn ends, as a lockstep game starts once
     * every agent's setup is over.
     */
    void setUp(long welcomeTick) {
        if (lockstep) {
            long setup = Math.max(tick, welcomeTick);
            session.send(s -> new EndTurnMessage(s, setup));
        }
    }

    /** The game is over: no turn is left waiting. */
    void close() {
        open = false;
    }

    /** A perception request was sent; during a lockstep turn it is applied at the end of this tick. */
    void requested(int every) {
        // The first perception then comes with the next tick.
        schedule.requested(every, (open || deciding) && lockstep ? tick + 1 : -1);
    }

    /**
     * How long to wait, in wall-clock time, for what an open turn still needs before taking it
     * without: longer when a perception is due for certain.
     */
    long waitMillis() {
        if (schedule.expect(tick) == PerceptionSchedule.Expect.YES) {
            return lockstep ? Long.MAX_VALUE : Math.max(5, 500 / tickRate); // in lockstep it comes with the Tick
        }
        return lockstep ? 50 : Math.max(5, 500 / tickRate);
    }
}
