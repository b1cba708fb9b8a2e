package io.orchard.server.sim;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.MessageTypes;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The game: the world, the agents in it, the clock and the rules. One thread owns it (the tick
 * thread of {@link TickLoop}, or a test calling {@link #beginTick()} and {@link #endTick()}); other
 * threads only hand it events through the {@link Inbox} methods, which queue them.
 *
 * <p>A tick runs in two halves. {@link #beginTick()} sends {@code Tick} to every client and the
 * perceptions that were asked for. Clients then act; {@link #endTick()} applies what they sent —
 * client by client in the order they connected, each client's messages in the order it sent them,
 * so that a seed and the same actions always give the same game — resolves grasps, advances the
 * agents that walk, and checks whether the game is over.
 */
public final class Simulation implements Inbox {

    /** Cell size of the grid that finds agents near a perceiving agent. */
    private static final double PERCEPTION_CELL = 25;

    private final World world;
    private final SimulationConfig config;
    private final long seed;
    private final String serverVersion;
    private final Recorder recorder;
    private final List<GameListener> listeners;
    private final MessageCodec codec = new MessageCodec();
    private final BlockingQueue<Event> inbox = new LinkedBlockingQueue<>();
    private final Random random;
    private final Placement placement;
    private final Actions actions;
    private final Perceptions perceptions;
    private final Grasps grasps;
    private final Walking walking;

    final Map<Long, ClientSession> sessions = new TreeMap<>();
    final Map<String, Agent> agents = new LinkedHashMap<>();
    final Scoreboard scores = new Scoreboard();
    private Phase phase = Phase.WAITING;
    private volatile long tick;
    private double time;
    private int fruitAtStart;
    private boolean scoresChanged;

    public Simulation(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                      List<GameListener> listeners) {
        this(world, config, seed, serverVersion, recorder, listeners, (name, radius) -> null);
    }

    /** A simulation that asks {@code placement} first where each new agent stands. */
    public Simulation(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                      List<GameListener> listeners, Placement placement) {
        this.world = world;
        this.config = config;
        this.seed = seed;
        this.serverVersion = serverVersion;
        this.recorder = recorder;
        this.listeners = List.copyOf(listeners);
        this.random = new Random(seed ^ 0x5DEECE66DL);
        this.placement = placement;
        this.walking = new Walking(this);
        this.actions = new Actions(this, world, walking);
        this.perceptions = new Perceptions(world);
        this.grasps = new Grasps(this, world);
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
    public WelcomeMessage welcome(long seq, Role role) {
        return new WelcomeMessage(seq, ProtocolVersion.CURRENT, serverVersion, role, world.bounds(), config.tickRate(),
                config.clock(), tick);
    }

    // ---- the tick thread ---------------------------------------------------------------------

    /** Takes the next queued event, waiting up to {@code millis}; null when none came. */
    Event poll(long millis) throws InterruptedException {
        return inbox.poll(millis, TimeUnit.MILLISECONDS);
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
        flushAll();
    }

    /** The first half of a tick: the clock and the perceptions asked for. */
    public void beginTick() {
        if (phase != Phase.RUNNING) {
            return;
        }
        broadcast(new TickMessage(tick, time), Audience.ALL);
        AgentGrid crowd = null;
        for (Agent agent : agents.values()) {
            if (agent.perceivesIn(tick)) {
                if (crowd == null) {
                    crowd = new AgentGrid(agents.values(), PERCEPTION_CELL);
                }
                for (ServerMessage perception : perceptions.of(agent, crowd, tick)) {
                    send(agent.owner, perception);
                }
                agent.perceptionRequested = false;
                if (agent.perceptionEvery > 0) {
                    agent.nextPerceptionTick = tick + agent.perceptionEvery;
                }
            }
        }
        flushAll();
    }

    /** The second half of a tick: apply what clients sent, resolve grasps, walk, check the end. */
    public void endTick() {
        List<Event> events = new ArrayList<>();
        drain(events);
        endTick(events);
    }

    void endTick(List<Event> events) {
        apply(events);
        if (phase == Phase.RUNNING) {
            grasps.resolve(tick, time);
            time = (tick + 1) * config.tickSeconds();
            walking.advance(time);
            if (scoresChanged) {
                broadcast(new io.orchard.protocol.message.ScoreUpdateMessage(tick, scores.ranking()), Audience.ALL);
                scoresChanged = false;
            }
            long ended = tick;
            tick++;
            checkGameOver();
            listeners.forEach(l -> l.tickEnded(ended, time));
        } else {
            grasps.clear();
        }
        flushAll();
    }

    private void apply(List<Event> events) {
        // Client by client in connection order, each client's events in the order it sent them.
        events.sort(Comparator.comparingLong(e -> e.session() == null ? -1 : e.session().id()));
        for (Event event : events) {
            if (event instanceof Event.Task task) {
                task.action().run();
            } else if (event instanceof Event.Connected connected) {
                join(connected.session());
            } else if (event instanceof Event.Disconnected gone) {
                leave(gone.session(), gone.reason());
            } else if (event instanceof Event.Received received && sessions.containsKey(received.session().id())) {
                recorder.accepted(tick, time, received.session().id(), received.message());
                handle(received.session(), received.message());
            }
        }
    }

    private void join(ClientSession session) {
        sessions.put(session.id(), session);
        if (session.role() == Role.VIEWER) {
            send(session, snapshot());
            for (Agent agent : agents.values()) {
                send(session, new AgentAddedMessage(tick, agent.state()));
            }
        }
    }

    private void leave(ClientSession session, String reason) {
        if (sessions.remove(session.id()) == null) {
            return;
        }
        List<Agent> owned = agents.values().stream().filter(a -> a.owner == session).toList();
        owned.forEach(agent -> removeAgent(agent, reason));
    }

    void removeAgent(Agent agent, String reason) {
        agents.remove(agent.name);
        broadcast(new AgentRemovedMessage(tick, agent.name, reason), Audience.ALL);
        listeners.forEach(l -> l.agentLeft(agent.name, reason));
    }

    private void handle(ClientSession session, ClientMessage message) {
        if (message instanceof RegisterMessage register) {
            register(session, register);
        } else if (message instanceof GameControlMessage control) {
            control(session, control);
        } else if (message instanceof InstructionMessage instruction) {
            route(session, instruction);
        } else if (message instanceof SayMessage say) {
            if (owned(session, say.seq(), say.agent()) != null) {
                broadcast(say, Audience.ALL);
            }
        } else if (message instanceof GraspRequestMessage grasp) {
            Agent agent = owned(session, grasp.seq(), grasp.agent());
            if (agent != null) {
                grasps.request(agent, grasp, phase == Phase.RUNNING);
            }
        } else if (!(message instanceof EndTurnMessage) && !(message instanceof HelloMessage)) {
            // EndTurn matters only to the tick loop; a second Hello is refused by the network layer.
            Agent agent = owned(session, message.seq(), actions.agentOf(message));
            if (agent != null) {
                actions.apply(agent, message, phase == Phase.RUNNING, time);
            }
        }
    }

    /** The session's agent of that name, or null after answering with the reason it is not. */
    Agent owned(ClientSession session, long seq, String name) {
        if (session.role() != Role.AGENT) {
            send(session, new ErrorMessage(seq, ErrorCode.WRONG_ROLE, "a viewer cannot drive agents"));
            return null;
        }
        Agent agent = agents.get(name);
        if (agent == null) {
            send(session, new ErrorMessage(seq, ErrorCode.UNKNOWN_AGENT, "no agent named '" + name + "' in the world"));
            return null;
        }
        if (agent.owner != session) {
            send(session, new ErrorMessage(seq, ErrorCode.NOT_YOUR_AGENT,
                    "agent '" + name + "' belongs to another connection"));
            return null;
        }
        return agent;
    }

    private void register(ClientSession session, RegisterMessage register) {
        long seq = register.seq();
        if (session.role() != Role.AGENT) {
            send(session, new ErrorMessage(seq, ErrorCode.WRONG_ROLE, "a viewer cannot register agents"));
        } else if (phase == Phase.OVER) {
            send(session, new ErrorMessage(seq, ErrorCode.GAME_NOT_RUNNING, "the game is over"));
        } else if (agents.containsKey(register.name())) {
            send(session, new ErrorMessage(seq, ErrorCode.NAME_IN_USE, "an agent named '" + register.name()
                    + "' is already in the world"));
        } else if (agents.values().stream().filter(a -> a.owner == session).count() >= config.agentsPerSession()) {
            send(session, new ErrorMessage(seq, ErrorCode.TOO_MANY_AGENTS, "a connection may drive at most "
                    + config.agentsPerSession() + " agents"));
        } else {
            var body = config.bodyLimits().cap(register.body());
            Vec3 place = placeFor(register.name(), body.radius());
            if (place == null) {
                send(session, new ErrorMessage(seq, ErrorCode.TOO_MANY_AGENTS, "no free place left for another agent"));
                return;
            }
            double heading = Angles.normalise(random.nextDouble() * 2 * Math.PI - Math.PI);
            Agent agent = new Agent(register.name(), session, body, register.model(), place, heading);
            agents.put(agent.name, agent);
            scores.join(agent.name);
            send(session, new RegisteredMessage(seq, agent.name, body, place, heading));
            broadcast(new AgentAddedMessage(tick, agent.state()), Audience.VIEWERS);
            listeners.forEach(l -> l.agentJoined(agent.name));
            if (phase == Phase.WAITING && agents.size() >= Math.max(1, config.waitFor())) {
                start();
            }
        }
    }

    /** A free place for a body of this radius: the placement's, or drawn from the seeded generator. */
    private Vec3 placeFor(String name, double radius) {
        Vec3 wanted = placement.placeFor(name, radius);
        if (wanted != null && world.checkPlace(wanted.onGround(), radius).isFree()
                && walking.clearOfAgents(wanted, radius, null)) {
            return Vec3.ground(wanted.x(), wanted.z());
        }
        for (int attempt = 0; attempt < 500; attempt++) {
            Vec3 candidate = world.randomFreePoint(random, radius + 0.1);
            if (candidate != null && walking.clearOfAgents(candidate, radius, null)) {
                return candidate;
            }
        }
        return null;
    }

    private void control(ClientSession session, GameControlMessage control) {
        String refused = switch (control.command()) {
            case START -> phase == Phase.WAITING ? null : "the game has already started";
            case PAUSE -> phase == Phase.RUNNING ? null : "the game is not running";
            case RESUME -> phase == Phase.PAUSED ? null : "the game is not paused";
        };
        if (refused != null) {
            send(session, new ActionResultMessage(control.seq(), null, "GameControl", Outcome.REJECTED, refused, null, 0));
            return;
        }
        switch (control.command()) {
            case START -> start();
            case PAUSE -> phase = Phase.PAUSED;
            case RESUME -> phase = Phase.RUNNING;
        }
        send(session, new ActionResultMessage(control.seq(), null, "GameControl", Outcome.ACCEPTED, null, null, 0));
    }

    /** Starts the game now (from a console or an embedding program); no effect once started. */
    public void start() {
        if (phase != Phase.WAITING) {
            return;
        }
        phase = Phase.RUNNING;
        fruitAtStart = world.fruitCount();
        broadcast(new GameStartedMessage(tick, seed, fruitAtStart, config.timeLimit()), Audience.ALL);
        listeners.forEach(l -> l.gameStarted(seed, fruitAtStart, config.timeLimit()));
    }

    /** Pauses a running game or continues a paused one; returns the phase after. */
    public Phase togglePause() {
        if (phase == Phase.RUNNING) {
            phase = Phase.PAUSED;
        } else if (phase == Phase.PAUSED) {
            phase = Phase.RUNNING;
        }
        return phase;
    }

    private void route(ClientSession from, InstructionMessage instruction) {
        Agent agent = agents.get(instruction.agent());
        if (agent == null) {
            send(from, new ErrorMessage(instruction.seq(), ErrorCode.UNKNOWN_AGENT,
                    "no agent named '" + instruction.agent() + "' in the world"));
            return;
        }
        send(agent.owner, instruction);
    }

    private void checkGameOver() {
        String reason = null;
        if (world.fruitCount() == 0) {
            reason = "all fruit collected";
        } else if (time >= config.timeLimit() - 1e-9) {
            reason = "time limit reached";
        }
        if (reason != null) {
            end(reason);
        }
    }

    /** Ends the game now with this reason; no effect once over. */
    public void end(String reason) {
        if (phase == Phase.OVER) {
            return;
        }
        phase = Phase.OVER;
        List<Score> ranking = scores.ranking();
        broadcast(new GameOverMessage(tick, reason, ranking), Audience.ALL);
        flushAll();
        String why = reason;
        listeners.forEach(l -> l.gameOver(why, ranking));
    }

    // ---- what other parts of the simulation use ----------------------------------------------

    void scoreChanged() {
        scoresChanged = true;
    }

    void fruitEaten(Agent agent, io.orchard.server.world.Fruit fruit) {
        listeners.forEach(l -> l.fruitEaten(agent.name, fruit.id(), fruit.kind(), time));
    }

    void send(ClientSession session, ServerMessage message) {
        recorder.sent(tick, time, Audience.CLIENT, session.id(), message);
        session.send(message);
    }

    void broadcast(ServerMessage message, Audience audience) {
        recorder.sent(tick, time, audience, 0, message);
        EncodedLine line = null;
        for (ClientSession session : sessions.values()) {
            boolean wanted = switch (audience) {
                case ALL -> true;
                case VIEWERS -> session.role() == Role.VIEWER;
                case AGENTS -> session.role() == Role.AGENT;
                case CLIENT -> false;
            };
            if (wanted) {
                if (line == null) {
                    line = EncodedLine.of(codec, message);
                }
                session.send(line);
            }
        }
    }

    private void flushAll() {
        sessions.values().forEach(ClientSession::flush);
    }

    WorldSnapshotMessage snapshot() {
        return world.snapshot(tick, time, scores.ranking());
    }

    // ---- state for the loop, the console and tests ---------------------------------------------

    /** The current phase. */
    public Phase phase() {
        return phase;
    }

    /** The tick that runs now (the next to begin, between ticks). */
    public long tick() {
        return tick;
    }

    /** Simulated seconds since the game started. */
    public double time() {
        return time;
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

    /** Sessions that drive at least one agent: the ones lockstep waits for. */
    List<Long> agentSessions() {
        return agents.values().stream().map(a -> a.owner.id()).distinct().sorted().toList();
    }

    boolean lockstep() {
        return config.clock() == ClockMode.LOCKSTEP;
    }

    static String typeOf(ClientMessage message) {
        return MessageTypes.nameOf(message.getClass());
    }
}
