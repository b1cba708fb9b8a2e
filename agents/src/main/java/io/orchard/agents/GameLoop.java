package io.orchard.agents;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.NewGameMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Outcome;
import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The agent's one game as its controller plays it, from connecting to {@code GameOver} (or to the
 * {@code NewGame} that follows it, for an agent that stays for the next game), on the
 * thread that called {@link AgentController#run}: it takes what happens one event at a time, keeps
 * the agent's situation, clock and counts up to date, and calls the controller's hooks, each
 * guarded so that a hook that throws is logged and the game goes on.
 */
final class GameLoop {

    private static final Logger log = LoggerFactory.getLogger(GameLoop.class);

    private final AgentController agent;
    private final String name;
    private final Session session;
    private final Situation situation;
    private final Turns turns;
    private final ControllerMotor motor;
    private final Tally tally;
    private final AgentRandom random;
    private final List<Consumer<String>> speechListeners = new CopyOnWriteArrayList<>();
    private final AtomicBoolean ran = new AtomicBoolean();
    private final List<Session.Instruction> early = new ArrayList<>();
    private GameOverMessage gameOver;
    /** Whether to stay connected once the game is over, for the operator's next game. */
    private volatile boolean stayForNextGame;
    /** Whether the server said that a next game waits. */
    private volatile boolean nextGame;
    /** Where the agent's resume token is kept across runs; null when it is not. */
    private volatile ResumeTokens resumeTokens;

    GameLoop(AgentController agent, Session session, Situation situation, Turns turns, ControllerMotor motor,
             Tally tally, AgentRandom random) {
        this.random = random;
        this.agent = agent;
        this.name = agent.name();
        this.session = session;
        this.situation = situation;
        this.turns = turns;
        this.motor = motor;
        this.tally = tally;
    }

    /**
     * Checks the model, connects, registers and plays until the game is over; null when stopped.
     *
     * @throws IllegalStateException when the agent has played before
     */
    @Nullable GameOverMessage run(String host, int port, @Nullable String token)
            throws IOException, InterruptedException {
        if (!ran.compareAndSet(false, true)) {
            throw new IllegalStateException("agent " + name + " has already played; make a new one for another game");
        }
        AgentBody plan = agent.declaredBody();
        ModelSpec model = Registration.model(agent.getClass(), name, plan);
        session.open(host, port, token);
        try {
            if (session.stopping()) {
                return null;
            }
            WelcomeMessage welcome = session.welcome();
            situation.welcomed(welcome);
            turns.welcomed(welcome);
            ResumeTokens tokens = resumeTokens;
            Registration.register(session, name, plan, model, tokens == null ? null : tokens.toPresent());
            return play();
        } finally {
            session.close();
            tally.publish();
        }
    }

    /** Keeps the agent's resume token in {@code file} from its next registration on. Safe from any thread. */
    void keepResumeTokensIn(ResumeTokenFile file) {
        resumeTokens = new ResumeTokens(file, name);
    }

    /** Hands the agent a console line as an instruction. Safe from any thread. */
    void instruct(String text) {
        session.instruct(new Session.Instruction(text, "console"));
    }

    /** Leaves the game: the connection closes, and {@link #run} returns. Safe from any thread. */
    void stop() {
        session.stop();
    }

    /** Stays connected once the game is over, until the server says a next game waits or closes. */
    void stayForNextGame() {
        stayForNextGame = true;
    }

    /** Whether the server started a next game after this one. */
    boolean nextGameWaits() {
        return nextGame;
    }

    /** Keep-alives after this much silence instead of every 30 s, for a server with a shorter idle rule. */
    void keepAliveEvery(Duration silence) {
        session.keepAliveEvery(silence);
    }

    /** What the agent has done so far, as published at the end of its latest turn. Safe from any thread. */
    AgentStats stats() {
        return tally.published();
    }

    /** Hears what the agent says, as the server relays it. Safe from any thread. */
    void addSpeechListener(Consumer<String> listener) {
        speechListeners.add(listener);
    }

    private GameOverMessage play() throws IOException, InterruptedException {
        while (gameOver == null || stayForNextGame && !nextGame) {
            Object event;
            if (turns.open()) {
                event = session.next(turns.waitMillis());
                if (event == null) {
                    turn(null); // the perception did not come in time: decide without it
                    continue;
                }
            } else {
                event = session.next();
            }
            if (event instanceof Session.Closed closed) {
                if (session.stopping() || gameOver != null) {
                    return gameOver;
                }
                throw new IOException("the server closed the connection of " + name
                        + (closed.cause() == null ? "" : ": " + closed.cause().getMessage()), closed.cause());
            }
            if (event instanceof Session.Instruction instruction) {
                instructed(instruction);
                continue;
            }
            handle((ServerMessage) event);
        }
        return gameOver;
    }

    private void handle(ServerMessage message) {
        if (message instanceof TickMessage t) {
            tick(t);
        } else if (message instanceof PerceptionMessage p) {
            if (p.agent().equals(name)) {
                turns.perceived(p);
            }
        } else if (message instanceof LandmarkPerceptionMessage l) {
            if (l.agent().equals(name)) {
                turns.perceived(l);
            }
        } else if (message instanceof CastlePerceptionMessage c) {
            if (c.agent().equals(name)) {
                perceived(c);
            }
        } else if (message instanceof ActionResultMessage result) {
            actionResult(result);
        } else if (message instanceof GraspResultMessage result) {
            graspResult(result);
        } else if (message instanceof FruitEatenMessage eaten) {
            if (situation.inWorld()) {
                situation.memory().fruitEaten(eaten.fruit());
                if (eaten.agent().equals(name)) {
                    situation.memory().collected(eaten.kind());
                }
            }
            guarded(() -> agent.onFruitEaten(eaten));
        } else if (message instanceof ScoreUpdateMessage update) {
            tally.scored(name, update.scores());
        } else if (message instanceof RegisteredMessage registered) {
            if (registered.agent().equals(name)) {
                registered(registered);
            }
        } else if (message instanceof InstructionMessage instruction) {
            if (instruction.agent().equals(name)) {
                instructed(new Session.Instruction(instruction.text(), instruction.from()));
            }
        } else if (message instanceof SayMessage say) {
            if (say.agent().equals(name)) {
                speechListeners.forEach(listener -> listener.accept(say.text()));
            } else {
                guarded(() -> agent.onHeard(say.agent(), say.text()));
            }
        } else if (message instanceof ErrorMessage error) {
            tally.errors++;
            session.answered(error.seq());
            guarded(() -> agent.onError(error));
        } else if (message instanceof GameStartedMessage started) {
            guarded(() -> agent.onGameStarted(started));
        } else if (message instanceof NewGameMessage) {
            nextGame = gameOver != null; // the game before is over: it came first
        } else if (message instanceof GameOverMessage over) {
            turns.close();
            tally.scored(name, over.ranking());
            gameOver = over;
            ResumeTokens tokens = resumeTokens;
            if (tokens != null) {
                tokens.gameOver();
            }
            guarded(() -> agent.onGameOver(over));
        }
    }

    private void instructed(Session.Instruction instruction) {
        if (situation.latest() != null) {
            guarded(() -> agent.onInstruction(instruction.text(), instruction.from()));
        } else {
            early.add(instruction); // the world not seen yet: kept for the first perception
        }
    }

    private void registered(RegisteredMessage registered) {
        situation.registered(registered);
        ResumeTokens tokens = resumeTokens;
        if (tokens != null) {
            tokens.registered(registered.resumeToken());
        }
        AgentBody plan = situation.plan();
        for (String joint : plan.joints()) {
            session.send(s -> new RegisterJointMessage(s, name, joint));
        }
        for (String sensor : plan.timeSensors()) {
            session.send(s -> new RegisterTimeSensorMessage(s, name, sensor));
        }
        motor.requestPerception(plan.perceptionEvery());
        if (registered.seed() != null) {
            random.reseed(registered.seed());
        }
        guarded(agent::onRegistered);
        turns.setUp(situation.welcome().tick());
    }

    private void tick(TickMessage t) {
        if (turns.lockstep()) {
            session.lockstepTicked();
        }
        if (turns.open()) {
            turn(null); // a tick began before the last one was decided: never leave a turn open
        }
        if (turns.began(t, situation.inWorld())) {
            turn(null);
        }
    }

    private void perceived(CastlePerceptionMessage castle) {
        Perception perception = turns.completed(castle);
        if (perception == null) {
            return;
        }
        situation.perceived(perception);
        for (Session.Instruction instruction : early) {
            guarded(() -> agent.onInstruction(instruction.text(), instruction.from()));
        }
        early.clear();
        if (turns.awaits(perception)) {
            turn(perception);
        }
    }

    private void turn(@Nullable Perception perception) {
        turns.take();
        motor.turnTaken(perception != null);
        guarded(() -> agent.onTick(turns.tick(), turns.time()));
        if (perception != null) {
            guarded(() -> agent.decide(perception));
        }
        motor.decided();
        turns.taken();
        tally.publish();
    }

    private void actionResult(ActionResultMessage result) {
        if (session.answered(result.seq()) instanceof MoveMessage move) {
            tally.moveAnswered(result.outcome(), result.reason());
            if (result.outcome() == Outcome.REJECTED) {
                log.debug("{} at tick {}: move {} rejected: {}", name, turns.tick(), move, result.reason());
            }
            motor.answered(result, move);
        }
        guarded(() -> agent.onActionResult(result));
    }

    private void graspResult(GraspResultMessage result) {
        session.answered(result.seq());
        if (result.success()) {
            tally.graspsWon++;
        } else {
            log.debug("{} at tick {}: grasp of {} failed: {}", name, turns.tick(), result.fruit(), result.reason());
        }
        motor.answered(result);
        guarded(() -> agent.onGraspResult(result));
    }

    private void guarded(Runnable hook) {
        try {
            hook.run();
        } catch (RuntimeException e) {
            log.warn("{}: a hook failed at tick {}", name, turns.tick(), e);
        }
    }
}
