package io.orchard.server.sim;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.NewGameMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.GamePhase;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.World;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.function.Consumer;
import java.util.function.LongFunction;

/**
 * The game: the world, the agents in it, the clock and the rules. One thread owns it (the tick
 * thread of {@link TickLoop}, or a test calling {@link #beginTick()} and {@link #endTick()}); other
 * threads only hand it events through the {@link Inbox} methods, which queue them.
 *
 * <p>A tick runs in two halves. {@link #beginTick()} sends {@code Tick} to every client and the
 * perceptions that were asked for. Clients then act; {@link #endTick()} applies what they sent —
 * client by client, each client's messages in the order it sent them ({@link EventOrder}), so that a
 * seed and the same actions always give the same game — resolves grasps, advances the agents that
 * walk, and checks whether the game is over.
 *
 * <p>It hands each part its share: what clients send and the clock to the {@link Outbox}, agents
 * entering and leaving to {@link Registrations}, every other message about an agent to
 * {@link Actions}, the phase to the {@link Game}, and in lockstep, whose turn is awaited and who
 * missed theirs to the {@link Turns}.
 */
public final class Simulation implements Inbox {

    /** Cell size of the grid that finds agents near a perceiving agent. */
    private static final double PERCEPTION_CELL = 25;

    private final SimulationConfig config;
    private final String serverVersion;
    private final List<GameListener> listeners;
    private final Placement placement;
    private final BlockingQueue<Event> inbox = new LinkedBlockingQueue<>();
    private final Outbox outbox;
    /** By name, so that every pass over the agents goes in an order that does not depend on timing. */
    final Map<String, Agent> agents = new TreeMap<>();
    private final CheckpointRequests checkpoints = new CheckpointRequests();
    /** Whether what the clients were sent at the end of the last tick waits for the next tick's start. */
    private boolean clientsWaiting;
    /** Ticks played in lockstep, every game together: read by the network threads. */
    private volatile long lockstepTicks;
    // The game's own parts: made anew when the operator restarts the game (newGame).
    private volatile World world;
    private volatile long seed;
    private Scoreboard scores;
    private volatile Game game;
    Registrations registrations;
    private Actions actions;
    private Perceptions perceptions;
    private Grasps grasps;
    private Walking walking;
    private Turns turns;
    private Duration nameReservation;
    /** Makes the world of a restarted game from its seed; null when this server plays one game only. */
    private LongFunction<World> worlds;
    /** Why a restart is refused when {@link #worlds} is null. */
    private String oneGameOnly = "this server plays one game only";
    /** The seed of the game the operator asked for, made at the end of this tick; null when none was. */
    private Long restartSeed;
    /** What waits for the restart asked for to be done. */
    private final List<Runnable> whenRestarted = new ArrayList<>();

    /** A simulation of {@code world} with no placement of its own: agents are placed where the world finds room. */
    public Simulation(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                      List<GameListener> listeners) {
        this(world, config, seed, serverVersion, recorder, listeners, (name, radius) -> null);
    }

    /** A simulation that asks {@code placement} first where each new agent stands. */
    public Simulation(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                      List<GameListener> listeners, Placement placement) {
        this.config = config;
        this.serverVersion = serverVersion;
        this.listeners = List.copyOf(listeners);
        this.placement = placement;
        this.outbox = new Outbox(recorder);
        newGame(world, seed);
        // A recording must replay with no viewer connected, so it opens with the world as viewers see
        // it: a broadcast to the viewers, of whom there are none yet.
        outbox.broadcast(snapshot(), Audience.VIEWERS);
    }

    /** The parts of a game of {@code world} made from {@code seed}, none of whose agents has come yet. */
    private void newGame(World world, long seed) {
        this.world = world;
        this.seed = seed;
        agents.clear();
        scores = new Scoreboard();
        game = new Game(world, config, seed, scores, outbox, listeners, this::beforeStart);
        walking = new Walking(agents, config.bodyLimits().maxRadius(), outbox);
        grasps = new Grasps(world, agents, scores, outbox, listeners);
        registrations = new Registrations(world, config, seed, placement, agents, scores, walking, game, outbox,
                listeners);
        if (nameReservation != null) {
            registrations.departed.reserveFor(nameReservation);
        }
        actions = new Actions(world, agents, walking, grasps, registrations, outbox);
        perceptions = new Perceptions(world);
        turns = new Turns();
    }

    // ---- Inbox: any thread -------------------------------------------------------------------

    @Override
    public void connected(ClientSession session) {
        inbox.add(new Event.Connected(session));
    }

    @Override
    public void received(ClientSession session, ClientMessage message) {
        inbox.add(new Event.Received(session, message));
    }

    @Override
    public void disconnected(ClientSession session, String reason) {
        inbox.add(new Event.Disconnected(session, reason));
    }

    /** Runs {@code action} on the simulation's thread, before the client events of the same tick. */
    public void execute(Runnable action) {
        inbox.add(new Event.Task(action));
    }

    @Override
    public long lockstepTicks() {
        return lockstepTicks;
    }

    @Override
    public WelcomeMessage welcome(long seq, Role role, int protocolVersion) {
        return new WelcomeMessage(seq, protocolVersion, serverVersion, role, world.bounds(), config.tickRate(),
                config.clock(), outbox.tick(), config.timeLimit(), GamePhase.valueOf(game.phase().name()))
                .forVersion(protocolVersion);
    }

    // ---- the tick thread ---------------------------------------------------------------------

    /** Takes the next queued event, waiting up to {@code millis} of the clock's time; null when none came. */
    Event poll(LoopClock clock, long millis) throws InterruptedException {
        return clock.poll(inbox, millis);
    }

    /** Moves every queued event into {@code into}. */
    void drain(List<Event> into) {
        inbox.drainTo(into);
    }

    /** Applies what clients sent while no ticks pass (before the game starts, while paused, after it ends). */
    public void applyNow() {
        List<Event> events = new ArrayList<>();
        drain(events);
        applyBuffered(events);
    }

    void applyBuffered(List<Event> events) {
        apply(events);
        restartIfAsked();
        if (game.startDue() && !agents.isEmpty() && turns.notSetUp(agentSessions()).isEmpty()) {
            game.start();
        }
        outbox.flush();
        checkpoints.applied(game.phase(), this::checkpoint);
    }

    /** The first half of a tick: the clock and the perceptions asked for. */
    public void beginTick() {
        if (!game.running()) {
            flushWaiting();
            return;
        }
        long tick = outbox.tick();
        if (lockstep()) {
            turns.began(agentSessions());
        }
        outbox.broadcast(new TickMessage(tick, outbox.time()), Audience.ALL);
        CrowdGrid.Query crowd = null;
        for (Agent agent : agents.values()) {
            if (agent.perceivesIn(tick)) {
                if (crowd == null) {
                    crowd = CrowdGrid.of(agents.values(), PERCEPTION_CELL);
                }
                outbox.send(agent.owner, perceptions.of(agent, crowd, tick));
                agent.perceptionRequested = false;
                if (agent.perceptionEvery > 0) {
                    agent.nextPerceptionTick = tick + agent.perceptionEvery;
                }
            }
        }
        clientsWaiting = false;
        outbox.flush();
    }

    /** Sends what the end of the last tick left for the next one, when none follows after all. */
    void flushWaiting() {
        if (clientsWaiting) {
            clientsWaiting = false;
            outbox.flush();
        }
    }

    /** The second half of a tick: apply what clients sent, resolve grasps, walk, check the end. */
    public void endTick() {
        List<Event> events = new ArrayList<>();
        drain(events);
        endTick(events);
    }

    void endTick(List<Event> events) {
        endTick(events, false);
    }

    /**
     * The second half of a tick; when {@code nextFollows} (the next tick begins at once, as in the
     * tick loop) and the game goes on, what the clients were sent waits for the next tick's
     * perceptions and goes out with them: one write per client per tick instead of two, for a delay
     * of the next tick's first half. What it sends is the same, in the same order.
     */
    void endTick(List<Event> events, boolean nextFollows) {
        boolean ticking = game.running();
        apply(events);
        boolean scored = false;
        // A pause that came during the tick takes effect once the tick is over, so that none is left half done.
        if (game.running() || ticking && game.phase() == Phase.PAUSED) {
            long tick = outbox.tick();
            if (lockstep()) {
                List<Long> present = agentSessions();
                turns.ended(tick, events, present).forEach((id, kind) -> missed(id, tick, kind));
            }
            boolean collected = grasps.resolve(tick, outbox.time());
            double time = (tick + 1) * config.tickSeconds();
            outbox.at(tick, time);
            walking.advance(time);
            if (collected) {
                outbox.broadcast(new ScoreUpdateMessage(tick, scores.ranking()), Audience.ALL);
                scored = true;
            }
            outbox.at(tick + 1, time);
            game.checkOver();
            if (lockstep()) {
                lockstepTicks = lockstepTicks + 1; // this thread alone writes it
            }
            listeners.forEach(l -> l.tickEnded(tick, time));
        } else {
            grasps.clear();
        }
        restartIfAsked();
        clientsWaiting = nextFollows && game.running();
        if (clientsWaiting) {
            outbox.flushRecord();
        } else {
            outbox.flush();
        }
        checkpoints.tickEnded(scored, game.phase(), this::checkpoint);
    }

    private void apply(List<Event> events) {
        for (Event event : EventOrder.inClientOrder(events, agents.values())) {
            outbox.from(event.session());
            if (event instanceof Event.Task task) {
                task.action().run();
            } else if (event instanceof Event.Connected connected) {
                join(connected.session());
            } else if (event instanceof Event.Disconnected gone) {
                turns.forget(gone.session().id());
                if (outbox.leave(gone.session())) {
                    registrations.leave(gone.session(), gone.reason());
                }
            } else if (event instanceof Event.Received received && outbox.connected(received.session())) {
                outbox.accepted(received.session(), received.message());
                handle(received.session(), received.message());
            }
        }
        outbox.from(null);
    }

    /** A viewer catches up with the game: not recorded, as the record holds the game already. */
    private void join(ClientSession session) {
        outbox.join(session);
        if (session.role() == Role.VIEWER) {
            outbox.catchUp(session, snapshot());
            for (Agent agent : agents.values()) {
                outbox.catchUp(session, new AgentAddedMessage(outbox.tick(), agent.state()));
            }
        }
        game.joinedLate(session);
    }

    /** Where each client message is handled: every message about one agent by {@link Actions}. */
    private void handle(ClientSession session, ClientMessage message) {
        if (message instanceof RegisterMessage register) {
            registrations.register(session, register);
        } else if (message instanceof GameControlMessage control && control.command() == GameCommand.RESTART) {
            restartAsked(session, control);
        } else if (message instanceof GameControlMessage control) {
            game.control(session, control);
        } else if (message instanceof InstructionMessage instruction) {
            route(session, instruction);
        } else if (message instanceof AgentMessage action) {
            actions.act(session, message.seq(), action, game.phase());
        } else if (message instanceof EndTurnMessage && game.phase() == Phase.WAITING
                && agents.values().stream().anyMatch(a -> a.owner == session)) {
            turns.setupEnded(session.id());
        }
        // A tick's EndTurn matters to the tick loop; a second Hello is refused by the network layer.
    }

    /**
     * The start of a lockstep game is due ({@link #startDue()}) but these agents' clients have not
     * ended their setup turns in time: they are recorded as missed, and the game starts without them.
     */
    public void startWithoutSetup() {
        if (!game.startDue()) {
            return;
        }
        for (Long id : turns.notSetUp(agentSessions())) {
            missed(id, outbox.tick(), MissedTurn.Kind.SETUP);
        }
        turns.setupMissed(turns.notSetUp(agentSessions()));
        game.start();
        outbox.flush();
    }

    /** Whether a lockstep game has its agents and starts once their setup turns are over. */
    public boolean startDue() {
        return game.startDue();
    }

    /** Just before the game starts: where the agents stand is settled in the order of their names. */
    private void beforeStart() {
        registrations.settle();
    }

    /** Records a turn the game went on without, and tells the listeners. */
    private void missed(long session, long tick, MissedTurn.Kind kind) {
        ClientSession client = null;
        List<String> names = new ArrayList<>();
        for (Agent agent : agents.values()) {
            if (agent.owner.id() == session) {
                client = agent.owner;
                names.add(agent.name);
            }
        }
        if (client == null) {
            return;
        }
        MissedTurn missed = new MissedTurn(tick, names, kind);
        outbox.from(client);
        outbox.missed(client, missed);
        outbox.from(null);
        listeners.forEach(l -> l.turnMissed(missed));
    }

    /** An instruction goes to the connection that drives the agent it names. */
    private void route(ClientSession from, InstructionMessage instruction) {
        Agent agent = agents.get(instruction.agent());
        if (agent == null) {
            outbox.send(from, new ErrorMessage(instruction.seq(), ErrorCode.UNKNOWN_AGENT,
                    "no agent named '" + instruction.agent() + "' in the world"));
            return;
        }
        outbox.send(agent.owner, instruction);
    }

    /** Starts the game now (from a console or an embedding program); no effect once started. */
    public void start() {
        game.start();
    }

    /** Pauses a running game or continues a paused one; returns the phase after. */
    public Phase togglePause() {
        return game.togglePause();
    }

    /** Ends the game now with this reason; no effect once over. */
    public void end(String reason) {
        game.end(reason);
    }

    // ---- restarts ------------------------------------------------------------------------------

    /**
     * Lets the operator restart the game ({@code GameControl restart}): {@code worlds} makes the new
     * game's world from its seed. Without it (the default) a restart is refused. Call before the
     * simulation's thread starts.
     */
    public void restartsWith(LongFunction<World> worlds) {
        this.worlds = worlds;
    }

    /**
     * Refuses the operator's restarts, with the reason given ("this server records its game").
     * Call before the simulation's thread starts.
     */
    public void oneGameOnly(String reason) {
        this.worlds = null;
        this.oneGameOnly = reason;
    }

    /**
     * Restarts the game at the end of the current tick (at once while no tick runs), as the operator
     * can, and then runs {@code done}. Call on the simulation's thread ({@link #execute}).
     *
     * @throws IllegalStateException when this server plays one game only, saying why
     */
    public void restart(long newSeed, Runnable done) {
        if (worlds == null) {
            throw new IllegalStateException(oneGameOnly);
        }
        restartSeed = newSeed;
        whenRestarted.add(done);
    }

    private void restartAsked(ClientSession session, GameControlMessage control) {
        boolean accepted = worlds != null;
        if (accepted) {
            restartSeed = control.seed() != null ? control.seed() : seed;
        }
        outbox.send(session, new ActionResultMessage(control.seq(), null, "GameControl",
                accepted ? Outcome.ACCEPTED : Outcome.REJECTED, accepted ? null : oneGameOnly, null, 0));
    }

    /**
     * The restart asked for in this tick: the game ends, if it is not over, and its agents leave the
     * world; a version 1 client, which knows of one game only, is let go; and a new game of a new
     * world waits for agents at tick 0, as on a new server. Every other client hears {@code NewGame},
     * and viewers the new world.
     */
    private void restartIfAsked() {
        if (restartSeed == null) {
            return;
        }
        long next = restartSeed;
        restartSeed = null;
        game.end("restarted by the operator");
        for (Agent agent : agents.values()) {
            outbox.broadcast(new AgentRemovedMessage(outbox.tick(), agent.name, "the game restarted"), Audience.ALL);
        }
        for (ClientSession client : outbox.clients()) {
            if (client.protocolVersion() < 2) {
                outbox.leave(client);
                client.close(new ErrorMessage(0, ErrorCode.GAME_NOT_RUNNING, "the game is over and the operator "
                        + "started another, which a version 1 client cannot follow: connect again to play it"));
            }
        }
        newGame(worlds.apply(next), next);
        outbox.at(0, 0);
        outbox.broadcast(new NewGameMessage(0, config.timeLimit()), Audience.ALL);
        outbox.broadcast(snapshot(), Audience.VIEWERS);
        listeners.forEach(l -> l.newGame(next));
        whenRestarted.forEach(Runnable::run);
        whenRestarted.clear();
    }

    // ---- checkpoints ---------------------------------------------------------------------------

    /**
     * Takes a checkpoint at the end of the current tick (at once while no ticks pass) and gives it
     * to {@code to} on the simulation's thread. Safe from any thread.
     */
    public void checkpointAtTickEnd(Consumer<Checkpoint> to) {
        execute(() -> checkpoints.atTickEnd(to));
    }

    /**
     * Gives {@code to} a checkpoint after every tick in which the scores changed and when the game
     * ends, so that nothing collected is lost to a crash. Call before the simulation's thread starts.
     */
    public void checkpointWhenScored(Consumer<Checkpoint> to) {
        checkpoints.whenScored(to);
    }

    /** The whole game as it is now. Call on the simulation's thread (or between steps, in a test). */
    public Checkpoint checkpoint() {
        List<Checkpoint.SavedAgent> saved = registrations.waiting();
        agents.values().forEach(agent -> saved.add(agent.saved()));
        return Checkpoint.of(seed, config, game.phase(), outbox.tick(), outbox.time(), game.fruitAtStart(), world,
                saved, scores.ranking());
    }

    /**
     * Continues a saved game: its clock, scores and phase; its agents wait, out of
     * the world, until their controllers register them again with their tokens. A running game
     * comes back paused and continues when every agent is back. Call before the simulation's thread
     * starts, on a simulation made from the checkpoint's world, seed and settings.
     */
    public void restore(Checkpoint checkpoint) {
        if (checkpoint.seed() != seed) {
            throw new IllegalArgumentException("the checkpoint is of seed " + checkpoint.seed() + ", this game of "
                    + seed);
        }
        outbox.at(checkpoint.tick(), checkpoint.time());
        checkpoint.scores().forEach(scores::restore);
        registrations.restore(checkpoint.agents());
        game.restore(checkpoint.gamePhase(), checkpoint.fruitAtStart(), !registrations.waiting().isEmpty());
        if (game.phase() != Phase.WAITING) {
            outbox.release(); // it started long ago: nothing to hold until the start
        }
        checkpoints.restored(game.phase());
    }

    /**
     * How long the name and score of an agent whose connection dropped stay its controller's (60 s
     * unless set): meanwhile whoever else registers the name gets {@code name_in_use}, saying when
     * it frees up, and the controller gets the agent back with its resume token. Zero frees the
     * name at once. Call before the simulation's thread starts.
     *
     * @throws IllegalArgumentException when {@code time} is negative
     */
    public void reserveDroppedNames(Duration time) {
        registrations.departed.reserveFor(time);
        nameReservation = time;
    }

    /**
     * Hands the game that has started over to a referee, for a program that goes on with its world
     * simulated in parts ({@link PartialSimulation}): its agents, registrations, reserved names,
     * scores, phase and turns. From now on what the referee says goes to {@code recorder} alone (the
     * caller hands it to the clients); this simulation is not used again. Call on the simulation's
     * thread.
     */
    public Referee referee(Recorder recorder) {
        outbox.recordOnly(recorder);
        return new Referee(world, config, seed, agents, registrations, game, scores, turns, outbox, walking,
                listeners, oneGameOnly);
    }

    /** Names of the agents of a restored game that are still waiting for their controllers. */
    public List<String> waitingAgents() {
        return registrations.waiting().stream().map(Checkpoint.SavedAgent::name).toList();
    }

    private WorldSnapshotMessage snapshot() {
        return world.snapshot(outbox.tick(), outbox.time(), scores.ranking());
    }

    // ---- state for the loop, the console and tests ---------------------------------------------

    /** The current phase. */
    public Phase phase() {
        return game.phase();
    }

    /** The tick that runs now (the next to begin, between ticks). */
    public long tick() {
        return outbox.tick();
    }

    /** Simulated seconds since the game started. */
    public double time() {
        return outbox.time();
    }

    /** The configuration in force. */
    public SimulationConfig config() {
        return config;
    }

    /** The seed the world was made from. */
    public long seed() {
        return seed;
    }

    /** Fruit still in the world. */
    public int fruitLeft() {
        return world.fruitCount();
    }

    /** Names of the agents in the world, in the order they joined. */
    public List<String> agentNames() {
        return List.copyOf(agents.keySet());
    }

    /** Every agent's score, best first. */
    public List<Score> ranking() {
        return scores.ranking();
    }

    /** Sessions that drive at least one agent, in the order of their agents' names. */
    List<Long> agentSessions() {
        return agents.values().stream().map(a -> a.owner.id()).distinct().toList();
    }

    /** The clients whose turns this lockstep tick waits for: those of agents, except the late ones. */
    List<Long> turnsToWaitFor() {
        return turns.waitFor();
    }

    /**
     * Writes out what the record held back while the game waited to start. Call once the
     * simulation's thread has stopped, before the recorder is closed.
     */
    public void stopped() {
        outbox.release();
    }

    boolean lockstep() {
        return config.clock() == ClockMode.LOCKSTEP;
    }
}
