package io.orchard.agents;

import io.orchard.agents.behaviour.Forager;
import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.errand.Errands;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.Obstruction;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.StopAnimationMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.LongFunction;
import java.util.random.RandomGenerator;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The base every Java agent extends. It connects to a server, registers the agent's body and model,
 * keeps the clock, builds a {@link WorldMemory} from the perceptions, and hands the agent what
 * happens through small hooks; the agent acts through small methods named after the paper's
 * messages. Override {@link #body()} and, for behaviour of your own, {@link #decide(Perception)}:
 * everything else has a default, and the default {@code decide} already explores and collects
 * fruit, and follows instructions in English such as "pick up the coconut on the table", "cross
 * the bridge" or "Guppy, stop".
 *
 * <h2>Instructions</h2>
 * A line typed on the agent's console ({@link #instruct}) or an {@code Instruction} relayed by the
 * server goes to {@link #onInstruction}: the default reads it with {@link #interpreter()} into a
 * {@link Goal}, ignores it when it was addressed to another agent by name, answers what it does
 * not understand with {@link #say}, and hands the goal to {@link #onGoal}. The default
 * {@code onGoal} gives it to the agent's {@link Errands}, which ground it in the memory, answer
 * with one line, ask which one is meant when the words fit several landmarks, and pursue it; an
 * agent's {@code decide} calls {@link #pursueInstruction()} first and does its own thing only when
 * that returns false. Override {@code onGoal} to handle goals yourself.
 *
 * <h2>The lifecycle</h2>
 * {@link #run(String, int)} does everything and returns when the game is over:
 * <ol>
 *   <li>reads the agent's model from its resources and checks it: a Transform named after the
 *       agent, and the nodes of its joints and time sensors ({@link AgentModel#check});
 *   <li>connects, registers the body with the model, then its joints and time sensors, and asks
 *       for a perception every tick ({@link AgentBody#perceptionEvery()}), and in lockstep mode ends
 *       its setup turn ({@code EndTurn}): the game starts when every agent's setup is over;
 *   <li>on each tick: waits for that tick's perception when one is due, adds it to the memory,
 *       calls {@link #onTick} and {@link #decide}, and in lockstep mode ends the turn for that
 *       tick ({@code EndTurn}); actions sent in {@code decide} are applied at the end of the tick;
 *   <li>on {@code GameOver}: calls {@link #onGameOver} and returns.
 * </ol>
 * The lifecycle is final; hooks are called one at a time on the thread that called {@code run}.
 * The server's answers to one tick's actions ({@link #onActionResult}, {@link #onGraspResult},
 * {@link #onFruitEaten}) arrive before the next tick.
 *
 * <h2>Threads</h2>
 * Only {@link #run}, {@link #instruct}, {@link #stop}, {@link #stats()}, {@link #name()},
 * {@link #declaredBody()} and {@link #addSpeechListener} are public, and they are the only methods
 * that may be called from other threads. Everything protected belongs to the controller's thread.
 */
public abstract class AgentController {

    private static final Logger log = LoggerFactory.getLogger(AgentController.class);
    private static final long REPLY_TIMEOUT_SECONDS = 10;
    private static final double GRASP_SECONDS = 1.5;

    private final String name;
    private final BlockingQueue<Object> inbox = new LinkedBlockingQueue<>();
    private final List<Consumer<String>> speechListeners = new CopyOnWriteArrayList<>();
    private final Map<Long, ClientMessage> sent = new HashMap<>();
    private final List<Instruction> early = new ArrayList<>();
    private final Motor motor = new ControllerMotor(this);
    private final Tally counters = new Tally();
    private final Throttle throttle = new Throttle(Throttle.RATE, Throttle.BURST);
    private final AgentRandom random;
    private volatile ProtocolConnection connection;
    private volatile AgentStats stats = AgentStats.NONE;
    private volatile boolean stopping;
    private AgentBody declared;
    private final Object bodyLock = new Object();
    private final AtomicBoolean ran = new AtomicBoolean();

    private AgentBody plan;
    private WelcomeMessage welcome;
    private Body body;
    private WorldMemory memory;
    private Perception latest;
    private Point2 position;
    private double heading;
    private long tick = -1;
    private double time;
    private boolean turnOpen;
    private PerceptionMessage pendingPerception;
    private LandmarkPerceptionMessage pendingLandmarks;
    private final PerceptionSchedule schedule = new PerceptionSchedule();
    private boolean deciding;
    private MoveStatus lastMove;
    private long lastMoveSeq = -1;
    private MoveStatus walk;
    private Point2 previousPosition;
    private boolean walkAnimating;
    private double animationBusyUntil = Double.NEGATIVE_INFINITY;
    private long posedTick = -1;
    private GraspStatus lastGrasp;
    private long lastGraspSeq = -1;
    private PathPlanner planner;
    private Forager forager;
    private Errands errands;
    private InstructionInterpreter interpreter;
    private GameOverMessage gameOver;

    /** The console line or relayed instruction, queued for the controller's thread. */
    private record Instruction(String text, String from) {}

    /** The connection closed. */
    private record Closed(Throwable cause) {}

    /**
     * An agent of this name: a letter, then up to 31 letters, digits, '_' or '-'. Its model's root
     * Transform must carry the same name.
     */
    protected AgentController(String name) {
        this.name = Checks.name(name, "agent name");
        this.random = new AgentRandom(name.hashCode() * 0x9E3779B97F4A7C15L);
    }

    // ---- the lifecycle: public and final -----------------------------------------------------

    /** The agent's name. */
    public final String name() {
        return name;
    }

    /**
     * Connects to the server at {@code host}:{@code port}, registers and plays until the game is
     * over. An agent plays one game.
     *
     * @return the server's {@code GameOver}, or null when {@link #stop()} ended the game for this agent
     * @throws ModelCheckException when the model lacks a node the agent registers
     * @throws IOException         when the model cannot be read, the server cannot be reached, refuses
     *                             the registration or closes the connection
     */
    public final GameOverMessage run(String host, int port) throws IOException, InterruptedException {
        return run(host, port, null);
    }

    /**
     * As {@link #run(String, int)}, presenting {@code token} to a server that requires one.
     *
     * @throws IllegalStateException when the agent has run before: an agent plays one game, make
     *                               a new one for the next
     */
    public final GameOverMessage run(String host, int port, @Nullable String token)
            throws IOException, InterruptedException {
        if (!ran.compareAndSet(false, true)) {
            throw new IllegalStateException("agent " + name + " has already played; make a new one for another game");
        }
        plan = declaredBody();
        ModelSpec model = model(plan);
        ProtocolConnection open = ProtocolConnection.connect(host, port, Role.AGENT, "orchard-agent-" + name, token,
                new ProtocolConnection.Listener() {
                    @Override
                    public void onMessage(ServerMessage message) {
                        inbox.add(message);
                    }

                    @Override
                    public void onClosed(Throwable cause) {
                        inbox.add(new Closed(cause));
                    }
                });
        connection = open;
        try {
            if (stopping) {
                return null;
            }
            welcome = open.welcome();
            register(open, model);
            return play();
        } finally {
            open.close();
            publishStats();
        }
    }

    /**
     * Hands the agent an instruction as if a person had sent it ({@link #onInstruction} with
     * {@code from} "console"). Instructions given before the agent's first perception are kept
     * until then, so that they are grounded in what it sees. Safe from any thread.
     */
    public final void instruct(String text) {
        inbox.add(new Instruction(Checks.text(text, "instruction"), "console"));
    }

    /** Leaves the game: closes the connection, and {@link #run} returns. Safe from any thread. */
    public final void stop() {
        stopping = true;
        ProtocolConnection open = connection;
        if (open != null) {
            open.close();
        }
    }

    /**
     * What the agent registers: its body, model, joints and time sensors, as {@link #body()}
     * declares them (asked once). Safe from any thread.
     */
    public final AgentBody declaredBody() {
        synchronized (bodyLock) {
            if (declared == null) {
                declared = Objects.requireNonNull(body(), "body() returned null");
            }
            return declared;
        }
    }

    /** What the agent has done so far (updated every tick). Safe from any thread. */
    public final AgentStats stats() {
        return stats;
    }

    /** Hears everything this agent says, as the server relays it (on the controller's thread). */
    public final void addSpeechListener(Consumer<String> listener) {
        speechListeners.add(Objects.requireNonNull(listener, "listener"));
    }

    // ---- what the agent is and does: override ------------------------------------------------

    /**
     * What the agent is: its body, model, joints and time sensors. Called once, before connecting.
     */
    protected abstract AgentBody body();

    /**
     * Decides this tick's actions from this tick's perception. Called once for each tick that has
     * a perception (every tick by default). The default pursues an instructed goal if there is
     * one ({@link #pursueInstruction()}), and otherwise explores and collects fruit
     * ({@link #forager()}).
     */
    protected void decide(Perception perception) {
        if (!pursueInstruction()) {
            forager().step();
        }
    }

    /** The agent is registered: its body in force is {@link #bodyInForce()}, its place {@link #position()}. */
    protected void onRegistered() {}

    /** The game started. */
    protected void onGameStarted(GameStartedMessage started) {}

    /** A tick starts; called before {@link #decide}, and on ticks without a perception too. */
    protected void onTick(long tickNumber, double seconds) {}

    /** The server answered an action (a move accepted, blocked or rejected with its reason...). */
    protected void onActionResult(ActionResultMessage result) {}

    /** The server answered a grasp. */
    protected void onGraspResult(GraspResultMessage result) {}

    /** Some agent (this one or another) collected a fruit; the memory has already forgotten it. */
    protected void onFruitEaten(FruitEatenMessage eaten) {}

    /** The server refused something this agent sent. */
    protected void onError(ErrorMessage error) {
        log.warn("{}: {} {}", name, error.code().wireName(), error.text());
    }

    /**
     * A person instructs the agent (a line typed on its console, or an {@code Instruction}
     * relayed by the server). The default reads it with {@link #interpreter()}:
     * <ul>
     *   <li>addressed to another agent by name ("Guppy, stop" heard by the Robot): answered with
     *       who it was for, and not acted on;
     *   <li>understood: the goal goes to {@link #onGoal};
     *   <li>not understood, while the agent waits for the answer to a question it asked: read as
     *       the answer ("the nearer one") if it is one;
     *   <li>otherwise not understood: the interpreter's helpful answer is said.
     * </ul>
     */
    protected void onInstruction(String text, @Nullable String from) {
        Interpretation heard = interpreter().interpret(text);
        if (!heard.isFor(name)) {
            say("That was for " + heard.addressee().orElseThrow() + ", not for me.");
            return;
        }
        if (heard instanceof Interpretation.Understood understood) {
            onGoal(understood.goal());
        } else if (heard instanceof Interpretation.NotUnderstood notUnderstood) {
            if (!errands().answer(text)) {
                say(errands().asking() ? notUnderstood.answer() + " " + errands().question()
                        : notUnderstood.answer());
            }
        }
    }

    /**
     * An instructed goal. The default hands it to the agent's {@link #errands()}, which answer the
     * person and pursue it in the ticks that follow ({@link #pursueInstruction()}). Override it to
     * pursue goals your own way: dispatch with {@code instanceof} on the goal's records
     * ({@link io.orchard.agents.language.Collect}, {@link io.orchard.agents.language.GoTo}, ...),
     * and answer with {@link #say}, as a person expects an answer.
     */
    protected void onGoal(Goal goal) {
        errands().take(goal);
    }

    /** Another agent said something. */
    protected void onHeard(String agent, String text) {}

    /** The game is over. */
    protected void onGameOver(GameOverMessage over) {}

    /**
     * Reads instructions into goals: the default understands simple English, as
     * docs/instructions.md describes, knowing this agent's name. Made once, on first use.
     */
    protected InstructionInterpreter interpreter() {
        if (interpreter == null) {
            interpreter = new InstructionInterpreter(List.of(name));
        }
        return interpreter;
    }

    // ---- what the agent knows ----------------------------------------------------------------

    /** The agent's memory of the world. */
    protected final WorldMemory memory() {
        return memory;
    }

    /** The body in force, as the server confirmed it at registration. */
    protected final Body bodyInForce() {
        return body;
    }

    /** Where the agent stands (its latest perception). */
    protected final Point2 position() {
        return position;
    }

    /** The agent's heading, including a turn sent during this tick. */
    protected final double heading() {
        return heading;
    }

    /** The current tick. */
    protected final long tick() {
        return tick;
    }

    /** Simulated seconds at the start of the current tick. */
    protected final double time() {
        return time;
    }

    /** The latest perception; null before the first. */
    protected final Perception latest() {
        return latest;
    }

    /** The server's welcome: the world's bounds, the tick rate, the clock. */
    protected final WelcomeMessage welcome() {
        return welcome;
    }

    /**
     * Random numbers: from the agent's own seed, which the server derives from the game's seed and the
     * agent's name, once registered (before, from the name), so that lockstep games repeat.
     */
    protected final RandomGenerator random() {
        return random;
    }

    /** The agent's actions as behaviours use them. */
    protected final Motor motor() {
        return motor;
    }

    /** Whether a move is under way: sent and not yet answered, or accepted and not yet over. */
    protected final boolean walking() {
        return (lastMove != null && !lastMove.answered()) || walk != null;
    }

    /** The latest move sent and, once it came, the server's answer; null before the first. */
    protected final @Nullable MoveStatus lastMove() {
        return lastMove;
    }

    /** The latest grasp sent and, once it came, the server's answer; null before the first. */
    protected final @Nullable GraspStatus lastGrasp() {
        return lastGrasp;
    }

    /**
     * The agent's path planner over its memory, made on first use once the agent is in the world.
     * One per agent: its map of the ground is kept up to date once, for every behaviour that plans.
     */
    protected final PathPlanner planner() {
        if (planner == null) {
            planner = new PathPlanner(memory);
        }
        return planner;
    }

    /**
     * The default autonomy ({@link Forager}), made on first use; its harvester plays the body's
     * grasp animation with each grasp.
     */
    protected final Forager forager() {
        if (forager == null) {
            forager = new Forager(memory, motor, planner(), random);
            String graspAnimation = plan.graspAnimation();
            if (graspAnimation != null) {
                forager.harvester().gesture(fruit -> play(graspAnimation, GRASP_SECONDS));
            }
        }
        return forager;
    }

    /**
     * The agent's instructed goals: the {@link Errands} that ground, answer and pursue them. Made
     * on first use, once the agent is in the world; its harvester plays the body's grasp
     * animation with each grasp.
     */
    protected final Errands errands() {
        if (errands == null) {
            errands = new Errands(memory, motor, planner());
            String graspAnimation = plan.graspAnimation();
            if (graspAnimation != null) {
                errands.harvester().gesture(fruit -> play(graspAnimation, GRASP_SECONDS));
            }
        }
        return errands;
    }

    /**
     * One tick of the instructed goal, if there is one: call it first in {@link #decide}.
     *
     * @return true when an instructed goal has the agent this tick (it acted, or stands still
     *         waiting for an answer), and the agent's own behaviour should rest; false in autonomy
     */
    protected final boolean pursueInstruction() {
        boolean held = memory != null && errands().step();
        if (held && forager != null) {
            forager.pause();
        }
        return held;
    }

    /** Whether an instructed goal has the agent: one is pursued, or a question waits for its answer. */
    protected final boolean instructed() {
        return errands != null && errands.busy();
    }

    // ---- what the agent does: the paper's actions --------------------------------------------

    /** Walks straight from where it stands to (x, z) (the paper's MoveMessage). */
    protected final void moveTo(double x, double z) {
        moveTo(new Point2(x, z));
    }

    /** Walks straight from where it stands to {@code to}. */
    protected final void moveTo(Point2 to) {
        Point2 from = position;
        long seq = send(s -> new MoveMessage(s, name, from.at(0), to.at(0)));
        lastMove = new MoveStatus(from, to, tick, null, null, Double.NaN);
        lastMoveSeq = seq;
        counters.movesSent++;
    }

    /** Turns to face {@code to}, then walks there. */
    protected final void walkTo(Point2 to) {
        face(to);
        moveTo(to);
    }

    /** Stops where it stands. */
    protected final void halt() {
        moveTo(position);
    }

    /** Turns on the spot to this heading (the paper's SetRotationMessage). */
    protected final void turnTo(double newHeading) {
        send(s -> new SetRotationMessage(s, name, Rotation.heading(newHeading)));
        heading = newHeading;
    }

    /** Turns to face a point. */
    protected final void face(Point2 point) {
        if (point.distance(position) > 1e-6) {
            turnTo(Bearings.headingTowards(position, point));
        }
    }

    /** Turns a registered joint (the paper's SetJointRotationMessage). */
    protected final void setJoint(String joint, Rotation rotation) {
        posedTick = tick;
        send(s -> new SetJointRotationMessage(s, name, joint, rotation));
    }

    /** Turns a registered joint by {@code angle} radians about the axis (x, y, z). */
    protected final void setJoint(String joint, double x, double y, double z, double angle) {
        setJoint(joint, new Rotation(new Vec3(x, y, z), angle));
    }

    /** Starts a registered animation (the paper's StartAnimationMessage). */
    protected final void startAnimation(String timeSensor, boolean loop) {
        send(s -> new StartAnimationMessage(s, name, timeSensor, loop));
    }

    /** Stops a registered animation (the paper's StopAnimationMessage). */
    protected final void stopAnimation(String timeSensor) {
        send(s -> new StopAnimationMessage(s, name, timeSensor));
    }

    /**
     * Plays a registered animation once, for {@code seconds}. The walk animation drives the same
     * joints, so it pauses meanwhile and resumes afterwards if the agent still walks.
     */
    protected final void play(String timeSensor, double seconds) {
        posedTick = tick;
        if (walkAnimating) {
            stopWalkAnimation(false);
        }
        startAnimation(timeSensor, false);
        animationBusyUntil = Math.max(animationBusyUntil, time + seconds);
    }

    /**
     * Grasps a fruit (the paper's GraspRequestMessage). The server grants it when the fruit is at
     * a height the gripper reaches, within the body's radius plus the gripper's reach plus the
     * fruit's radius, and within 60 degrees of the heading. Animate it with {@link #play} or
     * {@link #setJoint}.
     */
    protected final void grasp(String fruitId) {
        long seq = send(s -> new GraspRequestMessage(s, name, fruitId));
        lastGrasp = new GraspStatus(fruitId, tick, false, false, null);
        lastGraspSeq = seq;
        counters.graspsSent++;
    }

    /**
     * Asks for a perception at the start of the next tick and then every {@code every} ticks
     * (0: only the next one) (the paper's PerceptionRequestMessage).
     */
    protected final void requestPerception(int every) {
        if (every < 0) {
            throw new IllegalArgumentException("every must not be negative, was " + every);
        }
        send(s -> new PerceptionRequestMessage(s, name, every));
        // Sent during a lockstep turn, it is applied at the end of this tick: the first perception comes with the next.
        schedule.requested(every, (turnOpen || deciding) && welcome.clock() == ClockMode.LOCKSTEP ? tick + 1 : -1);
    }

    /** Says something to people; every client hears it, viewers show it. */
    protected final void say(String text) {
        String line = text.length() > Checks.MAX_TEXT ? text.substring(0, Checks.MAX_TEXT) : text;
        send(s -> new SayMessage(s, name, line));
    }

    // ---- the machinery -----------------------------------------------------------------------

    private ModelSpec model(AgentBody agentBody) throws IOException {
        if (agentBody.model() == null) {
            return null;
        }
        AgentModel model = AgentModel.load(getClass(), agentBody.model());
        if (agentBody.modelName() != null) {
            model = model.renamed(agentBody.modelName(), name);
        }
        model.check(name, agentBody.joints(), agentBody.timeSensors());
        return model.spec();
    }

    private void register(ProtocolConnection open, ModelSpec model) throws IOException, InterruptedException {
        Reply reply;
        try {
            reply = open.request(seq -> new RegisterMessage(seq, name, plan.body(), model))
                    .get(REPLY_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            throw new IOException("registration of " + name + " failed: " + e.getCause().getMessage(), e.getCause());
        } catch (TimeoutException e) {
            throw new IOException("no answer to the registration of " + name + " within " + REPLY_TIMEOUT_SECONDS + " s");
        }
        if (reply instanceof ErrorMessage error) {
            throw new IOException("the server refused to register " + name + ": " + error.code().wireName() + ": "
                    + error.text());
        }
    }

    private GameOverMessage play() throws IOException, InterruptedException {
        while (gameOver == null) {
            Object event;
            if (turnOpen) {
                event = inbox.poll(waitMillis(), TimeUnit.MILLISECONDS);
                if (event == null) {
                    turn(null); // the perception did not come in time: decide without it
                    continue;
                }
            } else {
                event = inbox.take();
            }
            if (event instanceof Closed closed) {
                if (stopping || gameOver != null) {
                    return gameOver;
                }
                throw new IOException("the server closed the connection of " + name
                        + (closed.cause() == null ? "" : ": " + closed.cause().getMessage()), closed.cause());
            }
            if (event instanceof Instruction instruction) {
                if (latest != null) {
                    guarded(() -> onInstruction(instruction.text(), instruction.from()));
                } else {
                    early.add(instruction); // the world not seen yet: kept for the first perception
                }
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
                pendingPerception = p;
                pendingLandmarks = null;
            }
        } else if (message instanceof LandmarkPerceptionMessage l) {
            if (l.agent().equals(name)) {
                pendingLandmarks = l;
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
            if (memory != null) {
                memory.fruitEaten(eaten.fruit());
            }
            guarded(() -> onFruitEaten(eaten));
        } else if (message instanceof ScoreUpdateMessage update) {
            for (Score score : update.scores()) {
                if (score.agent().equals(name)) {
                    counters.points = score.points();
                    counters.fruit = score.fruit();
                }
            }
        } else if (message instanceof RegisteredMessage registered) {
            if (registered.agent().equals(name)) {
                registered(registered);
            }
        } else if (message instanceof InstructionMessage instruction) {
            if (instruction.agent().equals(name)) {
                if (latest != null) {
                    guarded(() -> onInstruction(instruction.text(), instruction.from()));
                } else {
                    early.add(new Instruction(instruction.text(), instruction.from()));
                }
            }
        } else if (message instanceof SayMessage say) {
            if (say.agent().equals(name)) {
                speechListeners.forEach(listener -> listener.accept(say.text()));
            } else {
                guarded(() -> onHeard(say.agent(), say.text()));
            }
        } else if (message instanceof ErrorMessage error) {
            counters.errors++;
            sent.remove(error.seq());
            guarded(() -> onError(error));
        } else if (message instanceof GameStartedMessage started) {
            guarded(() -> onGameStarted(started));
        } else if (message instanceof GameOverMessage over) {
            if (turnOpen) {
                turnOpen = false;
            }
            for (Score score : over.ranking()) {
                if (score.agent().equals(name)) {
                    counters.points = score.points();
                    counters.fruit = score.fruit();
                }
            }
            gameOver = over;
            guarded(() -> onGameOver(over));
        }
    }

    private void registered(RegisteredMessage registered) {
        body = registered.body();
        position = registered.position().onGround();
        heading = registered.heading();
        memory = new WorldMemory(welcome.bounds(), body.radius(), body.sight());
        memory.placed(position, heading);
        for (String joint : plan.joints()) {
            send(s -> new RegisterJointMessage(s, name, joint));
        }
        for (String sensor : plan.timeSensors()) {
            send(s -> new RegisterTimeSensorMessage(s, name, sensor));
        }
        requestPerception(plan.perceptionEvery());
        if (registered.seed() != null) {
            random.reseed(registered.seed());
        }
        guarded(this::onRegistered);
        if (welcome.clock() == ClockMode.LOCKSTEP) {
            // The setup turn: a lockstep game starts once every agent's setup is over.
            long setup = Math.max(tick, welcome.tick());
            send(s -> new EndTurnMessage(s, setup));
        }
    }

    private void tick(TickMessage t) {
        if (turnOpen) {
            turn(null); // a tick began before the last one was decided: never leave a turn open
        }
        tick = t.tick();
        time = t.time();
        if (memory == null) {
            return;
        }
        turnOpen = true;
        if (pendingPerception != null && pendingPerception.tick() < tick) {
            pendingPerception = null;
            pendingLandmarks = null;
        }
        PerceptionSchedule.Expect expect = schedule.expect(tick);
        // In lockstep, waiting a while for a perception that may come would let the wall clock decide.
        if (expect == PerceptionSchedule.Expect.NO
                || (expect == PerceptionSchedule.Expect.MAYBE && welcome.clock() == ClockMode.LOCKSTEP)) {
            turn(null);
        }
    }

    private long waitMillis() {
        boolean lockstep = welcome.clock() == ClockMode.LOCKSTEP;
        if (schedule.expect(tick) == PerceptionSchedule.Expect.YES) {
            return lockstep ? Long.MAX_VALUE : Math.max(5, 500 / welcome.tickRate()); // it comes with the Tick
        }
        return lockstep ? 50 : Math.max(5, 500 / welcome.tickRate());
    }

    private void perceived(CastlePerceptionMessage castle) {
        PerceptionMessage seen = pendingPerception;
        if (seen == null || seen.tick() != castle.tick()) {
            return;
        }
        Perception perception = new Perception(seen, pendingLandmarks, castle);
        pendingPerception = null;
        pendingLandmarks = null;
        memory.perceive(seen, perception.landmarks(), castle);
        schedule.perceived(seen.tick());
        previousPosition = position;
        position = perception.ground();
        heading = perception.heading();
        latest = perception;
        for (Instruction instruction : early) {
            guarded(() -> onInstruction(instruction.text(), instruction.from()));
        }
        early.clear();
        if (turnOpen && seen.tick() == tick) {
            turn(perception);
        }
    }

    private void turn(Perception perception) {
        turnOpen = false;
        deciding = true;
        updateWalk(perception);
        guarded(() -> onTick(tick, time));
        if (perception != null) {
            guarded(() -> decide(perception));
        }
        animateWalk();
        deciding = false;
        if (welcome.clock() == ClockMode.LOCKSTEP) {
            long ended = tick;
            send(s -> new EndTurnMessage(s, ended));
        }
        publishStats();
    }

    /** Plays the walk animation while the agent walks, unless another animation has the joints. */
    private void animateWalk() {
        String walkAnimation = plan.walkAnimation();
        if (walkAnimation == null) {
            return;
        }
        boolean walking = walking() && lastMove != null && !lastMove.rejected()
                && lastMove.from().distance(lastMove.to()) > 1e-6;
        if (walkAnimating && !walking) {
            stopWalkAnimation(posedTick != tick);
        } else if (!walkAnimating && walking && time >= animationBusyUntil) {
            startAnimation(walkAnimation, true);
            walkAnimating = true;
        }
    }

    /**
     * Stops the walk animation; a stopped animation freezes where it is, so the joints it drives
     * go back to their neutral pose unless the agent posed them during this tick.
     */
    private void stopWalkAnimation(boolean toNeutral) {
        stopAnimation(plan.walkAnimation());
        walkAnimating = false;
        if (toNeutral) {
            Rotation neutral = new Rotation(new Vec3(1, 0, 0), 0);
            for (String joint : plan.joints()) {
                send(s -> new SetJointRotationMessage(s, name, joint, neutral));
            }
        }
    }

    /** Ends the walk when it is over, or when the agent stood still although it should walk (another agent stopped it). */
    private void updateWalk(Perception perception) {
        if (walk == null) {
            return;
        }
        if (time >= walk.endsAt() - 1e-9) {
            walk = null;
        } else if (perception != null && previousPosition != null && walk.tick() < tick - 1
                && previousPosition.distance(position) < 1e-3) {
            walk = null;
        }
    }

    private void actionResult(ActionResultMessage result) {
        ClientMessage what = sent.remove(result.seq());
        if (what instanceof MoveMessage) {
            switch (result.outcome()) {
                case ACCEPTED -> counters.movesAccepted++;
                case BLOCKED -> counters.movesBlocked++;
                case REJECTED -> {
                    counters.movesRejected++;
                    if (Obstruction.of(result.reason()).isObstacle()) {
                        counters.obstacleRejections++;
                    }
                    log.debug("{} at tick {}: move {} rejected: {}", name, tick, what, result.reason());
                }
            }
            if (result.seq() == lastMoveSeq) {
                moveAnswered(result);
            } else if (result.outcome() == Outcome.REJECTED && memory != null && what instanceof MoveMessage m) {
                memory.moveRejected(m.from().onGround(), m.to().onGround(), result.reason());
            }
        }
        guarded(() -> onActionResult(result));
    }

    private void moveAnswered(ActionResultMessage result) {
        MoveStatus asked = lastMove;
        double start = asked.tick() / (double) welcome.tickRate();
        if (result.outcome() == Outcome.REJECTED) {
            lastMove = new MoveStatus(asked.from(), asked.to(), asked.tick(), Outcome.REJECTED, result.reason(), start);
            if (memory != null && result.reason() != null) {
                memory.moveRejected(asked.from(), asked.to(), result.reason());
            }
        } else {
            Point2 end = result.position() == null ? asked.to() : result.position().onGround();
            lastMove = new MoveStatus(asked.from(), end, asked.tick(), result.outcome(), result.reason(),
                    start + result.duration());
            walk = result.duration() > 0 ? lastMove : null;
        }
    }

    private void graspResult(GraspResultMessage result) {
        sent.remove(result.seq());
        if (!result.success()) {
            log.debug("{} at tick {}: grasp of {} failed: {}", name, tick, result.fruit(), result.reason());
        }
        if (result.success()) {
            counters.graspsWon++;
        }
        if (result.seq() == lastGraspSeq) {
            lastGrasp = new GraspStatus(result.fruit(), lastGrasp.tick(), true, result.success(), result.reason());
        }
        guarded(() -> onGraspResult(result));
    }

    private long send(LongFunction<? extends ClientMessage> message) {
        ProtocolConnection open = connection;
        if (open == null || !open.isOpen()) {
            return -1;
        }
        try {
            throttle.acquire();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return -1;
        }
        try {
            return open.send(seq -> {
                ClientMessage built = message.apply(seq);
                if (!(built instanceof EndTurnMessage || built instanceof SayMessage)) {
                    sent.put(seq, built); // the server answers it: remember what it was
                }
                return built;
            });
        } catch (IOException e) {
            log.debug("{}: could not send: {}", name, e.getMessage());
            return -1;
        }
    }

    private void guarded(Runnable hook) {
        try {
            hook.run();
        } catch (RuntimeException e) {
            log.warn("{}: a hook failed at tick {}", name, tick, e);
        }
    }

    private void publishStats() {
        stats = counters.snapshot();
    }
}
