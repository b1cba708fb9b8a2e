package io.orchard.server.sim;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.World;
import java.util.List;

/**
 * Where the game is in its life ({@link Phase}) and what moves it on: enough agents, a command, a
 * pause, the fruit gone or the time up, and, for a restored game, its agents all back.
 *
 * <p>In lockstep, enough agents do not start the game at once: the start is then due, and comes
 * once their clients have ended their setup turns ({@link Turns}), so that every agent's setup is
 * applied before tick 0, whichever registered last.
 */
final class Game {

    private final World world;
    private final SimulationConfig config;
    private final long seed;
    private final Scoreboard scores;
    private final Outbox outbox;
    private final List<GameListener> listeners;
    /** Run just before the game starts: the last of the waiting. */
    private final Runnable beforeStart;
    /** Read by the network threads for their welcomes. */
    private volatile Phase phase = Phase.WAITING;
    /** In lockstep: enough agents came, and the game starts when their setup turns are over. */
    private boolean startDue;
    private int fruitAtStart;
    /** Whether a restored game continues by itself once every waiting agent is back. */
    private boolean continueWhenAllBack;

    Game(World world, SimulationConfig config, long seed, Scoreboard scores, Outbox outbox,
         List<GameListener> listeners, Runnable beforeStart) {
        this.beforeStart = beforeStart;
        this.world = world;
        this.config = config;
        this.seed = seed;
        this.scores = scores;
        this.outbox = outbox;
        this.listeners = listeners;
    }

    Phase phase() {
        return phase;
    }

    boolean running() {
        return phase == Phase.RUNNING;
    }

    /** The fruit in the world when the game started. */
    int fruitAtStart() {
        return fruitAtStart;
    }

    /** Whether enough agents came to a lockstep game, which starts once their setup turns are over. */
    boolean startDue() {
        return startDue && phase == Phase.WAITING;
    }

    /** Starts the game now; no effect once started. */
    void start() {
        if (phase != Phase.WAITING) {
            return;
        }
        startDue = false;
        outbox.release();
        beforeStart.run();
        phase = Phase.RUNNING;
        fruitAtStart = world.fruitCount();
        // The world's seed would give the world away to an agent: only viewers hear it.
        GameStartedMessage started = new GameStartedMessage(outbox.tick(), seed, fruitAtStart, config.timeLimit());
        outbox.broadcast(started, Audience.VIEWERS);
        outbox.broadcast(started.withoutSeed(), Audience.AGENTS);
        listeners.forEach(l -> l.gameStarted(seed, fruitAtStart, config.timeLimit()));
    }

    /**
     * Tells a client that connected after the start what it missed: the {@code GameStarted} of this
     * game, the seed for viewers only. Nothing while the game waits (it will hear the start) or is over.
     */
    void joinedLate(ClientSession session) {
        if (phase == Phase.RUNNING || phase == Phase.PAUSED) {
            // A game's first tick is 0, wherever it is now.
            GameStartedMessage started = new GameStartedMessage(0, seed, fruitAtStart, config.timeLimit());
            outbox.catchUp(session, session.role() == Role.VIEWER ? started : started.withoutSeed());
        }
    }

    /** A new agent entered, and {@code present} are in the world: the game starts when enough came. */
    void agentEntered(int present) {
        if (phase == Phase.WAITING && present >= Math.max(1, config.waitFor())) {
            if (config.clock() == ClockMode.LOCKSTEP) {
                startDue = true;
            } else {
                start();
            }
        }
    }

    /** Every agent of a restored game is back: a game that was running goes on. */
    void allBack() {
        if (continueWhenAllBack && phase == Phase.PAUSED) {
            phase = Phase.RUNNING;
            continueWhenAllBack = false;
        }
    }

    /** A client's start, pause or resume (not restart), answered with whether it was done. */
    void control(ClientSession session, GameControlMessage control) {
        String refused = switch (control.command()) {
            case START -> phase == Phase.WAITING ? null : "the game has already started";
            case PAUSE -> phase == Phase.RUNNING ? null : "the game is not running";
            case RESUME -> phase == Phase.PAUSED ? null : "the game is not paused";
            case RESTART -> throw new IllegalArgumentException("a restart makes a new game: the simulation's to do");
        };
        if (refused != null) {
            outbox.send(session, new ActionResultMessage(control.seq(), null, "GameControl", Outcome.REJECTED, refused,
                    null, 0));
            return;
        }
        continueWhenAllBack = false; // whoever pauses or resumes now decides
        switch (control.command()) {
            case START -> start();
            case PAUSE -> phase = Phase.PAUSED;
            case RESUME -> phase = Phase.RUNNING;
        }
        outbox.send(session, new ActionResultMessage(control.seq(), null, "GameControl", Outcome.ACCEPTED, null, null,
                0));
    }

    /** Pauses a running game or continues a paused one; returns the phase after. */
    Phase togglePause() {
        continueWhenAllBack = false;
        if (phase == Phase.RUNNING) {
            phase = Phase.PAUSED;
        } else if (phase == Phase.PAUSED) {
            phase = Phase.RUNNING;
        }
        return phase;
    }

    /** Ends the game when the fruit is gone or the time is up. */
    void checkOver() {
        String reason = null;
        if (world.fruitCount() == 0) {
            reason = "all fruit collected";
        } else if (outbox.time() >= config.timeLimit() - 1e-9) {
            reason = "time limit reached";
        }
        if (reason != null) {
            end(reason);
        }
    }

    /** Ends the game now with this reason; no effect once over. */
    void end(String reason) {
        if (phase == Phase.OVER) {
            return;
        }
        phase = Phase.OVER;
        startDue = false;
        outbox.release(); // a game ended before it started: what was held comes before the end
        List<Score> ranking = scores.ranking();
        outbox.broadcast(new GameOverMessage(outbox.tick(), reason, ranking), Audience.ALL);
        outbox.flush();
        outbox.stopRecording();
        listeners.forEach(l -> l.gameOver(reason, ranking));
    }

    /**
     * Takes up a saved game's phase. A running game comes back paused while agents are still to come
     * back ({@code waiting}), and then continues by itself.
     */
    void restore(Phase saved, int fruitAtStart, boolean waiting) {
        this.fruitAtStart = fruitAtStart;
        phase = saved;
        if (phase == Phase.RUNNING) {
            phase = waiting ? Phase.PAUSED : Phase.RUNNING;
            continueWhenAllBack = true;
        }
    }
}
