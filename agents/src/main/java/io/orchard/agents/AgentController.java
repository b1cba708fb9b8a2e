package io.orchard.agents;

import io.orchard.agents.behaviour.Forager;
import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.errand.Errands;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpreter;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.LanguageModel;
import io.orchard.agents.language.LanguageModelInterpreter;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import java.util.function.Consumer;
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
 * the bridge" or "Guppy, stop" ({@link #onInstruction}).
 *
 * <p>{@link #run(String, int)} does everything and returns when the game is over. On each tick it
 * waits for that tick's perception when one is due, adds it to the memory, calls {@link #onTick}
 * and {@link #decide}, and in lockstep mode ends the turn; actions are applied at the end of the
 * tick, and the server's answers to them ({@link #onActionResult}, ...) arrive before the next.
 * The lifecycle is final. Hooks are called one at a time on the thread that called {@code run},
 * which everything protected belongs to; only the public methods are safe from other threads.
 */
public abstract class AgentController {

    private static final Logger log = LoggerFactory.getLogger(AgentController.class);

    private final String name;
    private final AgentRandom random;
    private final Situation situation = new Situation();
    private final ControllerMotor motor;
    private final Behaviours behaviours;
    private volatile @Nullable LanguageModel languageModel;
    private volatile @Nullable LanguageModelInterpreter consulting;
    private final GameLoop loop;

    /**
     * An agent of this name: a letter, then up to 31 letters, digits, '_' or '-'. Its model's root
     * Transform must carry the same name.
     */
    protected AgentController(String name) {
        this.name = Checks.name(name, "agent name");
        this.random = new AgentRandom(name.hashCode() * 0x9E3779B97F4A7C15L);
        Session session = new Session(name);
        Turns turns = new Turns(session);
        Tally tally = new Tally();
        this.motor = new ControllerMotor(name, session, situation, turns, tally);
        this.behaviours = new Behaviours(name, situation, motor, random);
        this.loop = new GameLoop(this, session, situation, turns, motor, tally, random);
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
     * @throws IllegalStateException when the agent has run before: make a new one for another game
     */
    public final GameOverMessage run(String host, int port, @Nullable String token)
            throws IOException, InterruptedException {
        return loop.run(host, port, token);
    }

    /**
     * Keeps the agent's resume token in {@code file}, so that running the agent again after its
     * connection dropped, or after its server was restarted from a checkpoint, gets it back where it
     * was, with its score (docs/protocol.md, 11.4). {@link #run} then registers with the token the
     * file holds for the agent's name, if any; writes the one the server gives; and removes it when
     * the game is over. Several agents, in one program or in several, may share one file (a line
     * each). The file is written whole and renamed into place, readable by its owner only where the
     * file system has POSIX permissions: a token is the agent's password. A file that cannot be
     * read or written is logged, and the agent plays without it. Call it before {@code run}.
     * {@code ./orchard agent} and {@code ./orchard agents} keep theirs in
     * {@code ~/.orchard/resume-tokens} unless told otherwise ({@code --resume-tokens FILE}).
     */
    public final void keepResumeTokensIn(Path file) {
        loop.keepResumeTokensIn(new ResumeTokenFile(Objects.requireNonNull(file, "resume token file")));
    }

    /**
     * Hands the agent an instruction as if a person had sent it ({@link #onInstruction} with
     * {@code from} "console"). Instructions given before the agent's first perception are kept
     * until then, so that they are grounded in what it sees. Safe from any thread.
     */
    public final void instruct(String text) {
        loop.instruct(Checks.text(text, "instruction"));
    }

    /**
     * Stays connected once the game is over, for the next game that the server's operator may start
     * ({@code GameControl restart}, docs/protocol.md 11.6): {@link #run} then returns the
     * {@code GameOver} when the server says that game waits ({@link #nextGameWaits()}), or when it
     * closes the connection. An agent plays one game: a new agent plays the next, as a new run of the
     * program would. Call before {@code run}.
     */
    public final void stayForNextGame() {
        loop.stayForNextGame();
    }

    /**
     * Whether the server started another game after this agent's, for a new agent to play
     * ({@link #stayForNextGame()}). Safe from any thread.
     */
    public final boolean nextGameWaits() {
        return loop.nextGameWaits();
    }

    /** Leaves the game: closes the connection, and {@link #run} returns. Safe from any thread. */
    public final void stop() {
        loop.stop();
    }

    /**
     * Sends a keep-alive after this much silence instead of every 30 s, for a server whose idle
     * rule is shorter than its default 120 s. Call before {@link #run}.
     */
    final void keepAliveEvery(Duration silence) {
        loop.keepAliveEvery(silence);
    }

    /** What the agent registers, as {@link #body()} declares it (asked once). Safe from any thread. */
    public final AgentBody declaredBody() {
        return situation.declared(this::body);
    }

    /** What the agent has done so far (updated every tick). Safe from any thread. */
    public final AgentStats stats() {
        return loop.stats();
    }

    /** Hears everything this agent says, as the server relays it (on the controller's thread). */
    public final void addSpeechListener(Consumer<String> listener) {
        loop.addSpeechListener(Objects.requireNonNull(listener, "listener"));
    }

    // ---- what the agent is and does: override ------------------------------------------------

    /** What the agent is: its body, model, joints and time sensors. Called once, before connecting. */
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
     * A person instructs the agent: a line typed on its console, or an {@code Instruction} relayed
     * by the server. The default reads it with {@link #interpreter()} and hands a goal it
     * understood to {@link #onGoal}; it answers one for another agent ("Guppy, stop" heard by the
     * Robot) with who it was for, reads one it did not understand as the answer to a question it
     * asked ("the nearer one") when it is one, and otherwise says the interpreter's helpful answer. The
     * sentence is read in what the agent spoke about or looked at last ({@link Errands#discourse()}), so
     * that "that table" is the table it just named.
     */
    protected void onInstruction(String text, @Nullable String from) {
        behaviours.heard(text, interpreter().interpret(text, behaviours.discourse()), this::onGoal);
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
     * Reads instructions into goals: the default, an {@link InstructionInterpreter}, understands simple
     * English (docs/instructions.md) and is made once; override to plug in another {@link Interpreter}.
     */
    protected Interpreter interpreter() {
        InstructionInterpreter grammar = behaviours.interpreter();
        LanguageModel model = languageModel;
        if (model == null) {
            return grammar;
        }
        LanguageModelInterpreter asking = consulting;
        if (asking == null || asking.grammar() != grammar) {
            asking = new LanguageModelInterpreter(grammar, model);
            consulting = asking;
        }
        return asking;
    }

    /**
     * Has the default {@link #interpreter()} ask a language model for the sentences its grammar does
     * not understand ({@link LanguageModelInterpreter}); off unless called. Whatever the grammar
     * understands is read as before, so games with the shipped agents stay reproducible.
     */
    public final void consultLanguageModel(LanguageModel model) {
        languageModel = Objects.requireNonNull(model, "model");
    }

    /**
     * Has the agent understand {@code language} as well as English ({@link Language#GERMAN}: "geh zum
     * Schloss", "was siehst du?"), read each sentence in the language it is in, and answer in that
     * language: what it says back, what it says as it carries the instruction out, and its answers to
     * questions. English ({@link Language#ENGLISH}) is every agent's and needs no call. Safe from any
     * thread; {@code ./orchard agent --language de} calls it.
     */
    public final void understand(Language language) {
        behaviours.understand(Objects.requireNonNull(language, "language"));
    }

    // ---- what the agent knows ----------------------------------------------------------------

    /** The agent's memory of the world. */
    protected final WorldMemory memory() {
        return situation.memory();
    }

    /** The body in force, as the server confirmed it at registration. */
    protected final Body bodyInForce() {
        return situation.body();
    }

    /** Where the agent stands (its latest perception). */
    protected final Point2 position() {
        return situation.position();
    }

    /** The agent's heading, including a turn sent during this tick. */
    protected final double heading() {
        return situation.heading();
    }

    /** The current tick. */
    protected final long tick() {
        return motor.tick();
    }

    /** Simulated seconds at the start of the current tick. */
    protected final double time() {
        return motor.time();
    }

    /** The latest perception; null before the first. */
    protected final Perception latest() {
        return situation.latest();
    }

    /** The server's welcome: the world's bounds, the tick rate, the clock. */
    protected final WelcomeMessage welcome() {
        return situation.welcome();
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
        return motor.walking();
    }

    /** The latest move sent and, once it came, the server's answer; null before the first. */
    protected final @Nullable MoveStatus lastMove() {
        return motor.lastMove();
    }

    /** The latest grasp sent and, once it came, the server's answer; null before the first. */
    protected final @Nullable GraspStatus lastGrasp() {
        return motor.lastGrasp();
    }

    /**
     * The agent's path planner over its memory, made on first use once the agent is in the world.
     * One per agent: its map of the ground is kept up to date once, for every behaviour that plans.
     */
    protected final PathPlanner planner() {
        return behaviours.planner();
    }

    /**
     * The default autonomy ({@link Forager}), made on first use; its harvester plays the body's
     * grasp animation with each grasp.
     */
    protected final Forager forager() {
        return behaviours.forager();
    }

    /**
     * The agent's instructed goals: the {@link Errands} that ground, answer and pursue them, made on
     * first use once the agent is in the world; its harvester plays the body's grasp animation.
     */
    protected final Errands errands() {
        return behaviours.errands();
    }

    /**
     * One tick of the instructed goal, if there is one: call it first in {@link #decide}.
     *
     * @return true when an instructed goal has the agent this tick (it acted, or stands still
     *         waiting for an answer), and the agent's own behaviour should rest; false in autonomy
     */
    protected final boolean pursueInstruction() {
        return behaviours.pursueInstruction();
    }

    /** Whether an instructed goal has the agent: one is pursued, or a question waits for its answer. */
    protected final boolean instructed() {
        return behaviours.instructed();
    }

    // ---- what the agent does: the paper's actions --------------------------------------------

    /** Walks straight from where it stands to (x, z) (the paper's MoveMessage). */
    protected final void moveTo(double x, double z) {
        moveTo(new Point2(x, z));
    }

    /** Walks straight from where it stands to {@code to}. */
    protected final void moveTo(Point2 to) {
        motor.moveTo(to);
    }

    /** Turns to face {@code to}, then walks there. */
    protected final void walkTo(Point2 to) {
        motor.moveTo(to, true);
    }

    /** Stops where it stands. */
    protected final void halt() {
        motor.halt();
    }

    /** Turns on the spot to this heading (the paper's SetRotationMessage). */
    protected final void turnTo(double newHeading) {
        motor.turnTo(newHeading);
    }

    /** Turns to face a point. */
    protected final void face(Point2 point) {
        motor.face(point);
    }

    /** Turns a registered joint (the paper's SetJointRotationMessage). */
    protected final void setJoint(String joint, Rotation rotation) {
        motor.setJoint(joint, rotation);
    }

    /** Turns a registered joint by {@code angle} radians about the axis (x, y, z). */
    protected final void setJoint(String joint, double x, double y, double z, double angle) {
        setJoint(joint, new Rotation(new Vec3(x, y, z), angle));
    }

    /** Starts a registered animation (the paper's StartAnimationMessage). */
    protected final void startAnimation(String timeSensor, boolean loop) {
        motor.startAnimation(timeSensor, loop);
    }

    /** Stops a registered animation (the paper's StopAnimationMessage). */
    protected final void stopAnimation(String timeSensor) {
        motor.stopAnimation(timeSensor);
    }

    /**
     * Plays a registered animation once, for {@code seconds}. The walk animation drives the same
     * joints, so it pauses meanwhile and resumes afterwards if the agent still walks.
     */
    protected final void play(String timeSensor, double seconds) {
        motor.play(timeSensor, seconds);
    }

    /**
     * Grasps a fruit (the paper's GraspRequestMessage). The server grants it when the fruit is at
     * a height the gripper reaches, within the body's radius plus the gripper's reach plus the
     * fruit's radius, and within 60 degrees of the heading. Animate it with {@link #play} or
     * {@link #setJoint}.
     */
    protected final void grasp(String fruitId) {
        motor.grasp(fruitId);
    }

    /**
     * Asks for a perception at the start of the next tick and then every {@code every} ticks
     * (0: only the next one) (the paper's PerceptionRequestMessage).
     */
    protected final void requestPerception(int every) {
        motor.requestPerception(every);
    }

    /** Says something to people; every client hears it, viewers show it. */
    protected final void say(String text) {
        motor.say(text);
    }
}
