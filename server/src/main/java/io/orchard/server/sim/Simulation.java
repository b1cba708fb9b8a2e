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
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
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

    /** The most different agent names a game takes: each keeps a score for the whole game. */
    static final int MAX_NAMES = 100_000;

    /** {@link #MAX_NAMES}, smaller in tests. */
    int maxNames = MAX_NAMES;

    /** Cell size of the grid that finds agents near a perceiving agent. */
    private static final double PERCEPTION_CELL = 25;

    private final World world;
    private final SimulationConfig config;
    private final long seed;
    private final String serverVersion;
    /** Where the game is recorded; nothing after the game's end, so that the same game gives the same record. */
    private Recorder recorder;
    private final List<GameListener> listeners;
    /** Immutable and costly to build: one for every simulation. */
    private static final MessageCodec CODEC = new MessageCodec();
    private final BlockingQueue<Event> inbox = new LinkedBlockingQueue<>();
    private final SecureRandom secrets = new SecureRandom();
    private final Placement placement;
    private final Actions actions;
    private final Perceptions perceptions;
    private final Grasps grasps;
    private final Walking walking;

    final Map<Long, ClientSession> sessions = new TreeMap<>();
    private final Map<Long, ClientSession> viewers = new TreeMap<>();
    private final Map<Long, ClientSession> agentClients = new TreeMap<>();
    /** By name, so that every pass over the agents goes in an order that does not depend on timing. */
    final Map<String, Agent> agents = new TreeMap<>();
    final Scoreboard scores = new Scoreboard();
    private Phase phase = Phase.WAITING;
    private volatile long tick;
    private double time;
    private int fruitAtStart;
    private boolean scoresChanged;
    private long joins;
    /** Agents of a restored game, waiting for their controllers: their names are reserved. */
    private final Map<String, Checkpoint.SavedAgent> waiting = new LinkedHashMap<>();
    /** Agents whose connection dropped, kept so that their controllers can get them back. */
    private final Map<String, Checkpoint.SavedAgent> departed = new LinkedHashMap<>();
    /** Whether a restored game continues by itself once every waiting agent is back. */
    private boolean continueWhenAllBack;
    private boolean overSaved;
    private final List<Consumer<Checkpoint>> checkpointRequests = new ArrayList<>();
    private Consumer<Checkpoint> onScore;

    /** A simulation of {@code world} with no placement of its own: agents are placed where the world finds room. */
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
        this.placement = placement;
        this.walking = new Walking(this);
        this.actions = new Actions(this, world, walking);
        this.perceptions = new Perceptions(world);
        this.grasps = new Grasps(this, world);
        // A recording must replay with no viewer connected, so it opens with the world as viewers see it.
        recorder.sent(tick, time, Audience.VIEWERS, 0, snapshot());
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
        takeCheckpoints(false);
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
        boolean scored = false;
        if (phase == Phase.RUNNING) {
            grasps.resolve(tick, time);
            time = (tick + 1) * config.tickSeconds();
            walking.advance(time);
            if (scoresChanged) {
                broadcast(new io.orchard.protocol.message.ScoreUpdateMessage(tick, scores.ranking()), Audience.ALL);
                scoresChanged = false;
                scored = true;
            }
            long ended = tick;
            tick++;
            checkGameOver();
            listeners.forEach(l -> l.tickEnded(ended, time));
        } else {
            grasps.clear();
        }
        flushAll();
        takeCheckpoints(scored || phase == Phase.OVER && !overSaved);
    }

    private void apply(List<Event> events) {
        for (Event event : inClientOrder(events)) {
            if (event instanceof Event.Task task) {
                task.action().run();
            } else if (event instanceof Event.Connected connected) {
                join(connected.session());
            } else if (event instanceof Event.Disconnected gone) {
                leave(gone.session(), gone.reason());
            } else if (event instanceof Event.Received received && sessions.containsKey(received.session().id())) {
                recorder.accepted(tick, time, received.session().id(), withoutSecrets(received.message()));
                handle(received.session(), received.message());
            }
        }
    }

    private void join(ClientSession session) {
        sessions.put(session.id(), session);
        (session.role() == Role.VIEWER ? viewers : agentClients).put(session.id(), session);
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
        viewers.remove(session.id());
        agentClients.remove(session.id());
        List<Agent> owned = agents.values().stream().filter(a -> a.owner == session).toList();
        for (Agent agent : owned) {
            departed.remove(agent.name);
            departed.put(agent.name, saved(agent));
            removeAgent(agent, reason);
        }
    }

    void removeAgent(Agent agent, String reason) {
        agents.remove(agent.name);
        walking.agentsChanged();
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
        String name = register.name();
        Checkpoint.SavedAgent reserved = waiting.get(name);
        if (session.role() != Role.AGENT) {
            send(session, new ErrorMessage(seq, ErrorCode.WRONG_ROLE, "a viewer cannot register agents"));
        } else if (phase == Phase.OVER) {
            send(session, new ErrorMessage(seq, ErrorCode.GAME_NOT_RUNNING, "the game is over"));
        } else if (agents.containsKey(name)) {
            send(session, new ErrorMessage(seq, ErrorCode.NAME_IN_USE, "an agent named '" + name
                    + "' is already in the world"));
        } else if (reserved != null && !tokenMatches(reserved.resumeToken(), register.resumeToken())) {
            send(session, new ErrorMessage(seq, ErrorCode.NAME_IN_USE, "agent '" + name + "' of the saved game is "
                    + "waiting for its controller: register it with its resumeToken"));
        } else if (agents.values().stream().filter(a -> a.owner == session).count() >= config.agentsPerSession()) {
            send(session, new ErrorMessage(seq, ErrorCode.TOO_MANY_AGENTS, "a connection may drive at most "
                    + config.agentsPerSession() + " agents"));
        } else if (reserved != null) {
            if (resume(session, seq, reserved)) {
                waiting.remove(name);
            }
            if (waiting.isEmpty() && continueWhenAllBack && phase == Phase.PAUSED) {
                phase = Phase.RUNNING;
                continueWhenAllBack = false;
            }
        } else if (departed.containsKey(name) && tokenMatches(departed.get(name).resumeToken(), register.resumeToken())) {
            if (resume(session, seq, departed.get(name))) {
                departed.remove(name);
            }
        } else if (scores.size() >= maxNames && !scores.has(name)) {
            send(session, new ErrorMessage(seq, ErrorCode.TOO_MANY_AGENTS, "this game has had " + maxNames
                    + " different agents, the most it takes"));
        } else {
            var body = config.bodyLimits().cap(register.body());
            java.util.random.RandomGenerator draws = placing(name);
            Vec3 place = placeFor(name, body.radius(), draws);
            if (place == null) {
                send(session, new ErrorMessage(seq, ErrorCode.TOO_MANY_AGENTS, "no free place left for another agent"));
                return;
            }
            double heading = Angles.normalise(draws.nextDouble() * 2 * Math.PI - Math.PI);
            departed.remove(name);
            enter(session, seq, new Agent(name, session, body, register.model(), place, heading, newToken()));
            if (phase == Phase.WAITING && agents.size() >= Math.max(1, config.waitFor())) {
                start();
            }
        }
    }

    /**
     * Puts a saved agent back: where it stood if that place is still free, else at a free place.
     * Returns false, having answered why, when there is no free place left.
     */
    private boolean resume(ClientSession session, long seq, Checkpoint.SavedAgent saved) {
        Vec3 place = saved.position();
        double radius = saved.body().radius();
        if (!world.checkPlace(place.onGround(), radius).isFree() || !walking.clearOfAgents(place, radius, null)) {
            place = placeFor(saved.name(), radius, placing(saved.name()));
            if (place == null) {
                send(session, new ErrorMessage(seq, ErrorCode.TOO_MANY_AGENTS, "no free place left for another agent"));
                return false;
            }
        }
        Agent agent = new Agent(saved.name(), session, saved.body(), saved.model(), place, saved.heading(),
                saved.resumeToken());
        agent.joints.addAll(saved.joints());
        agent.timeSensors.addAll(saved.timeSensors());
        enter(session, seq, agent);
        return true;
    }

    private void enter(ClientSession session, long seq, Agent agent) {
        agent.joined = ++joins;
        agents.put(agent.name, agent);
        walking.agentsChanged();
        scores.join(agent.name);
        send(session, new RegisteredMessage(seq, agent.name, agent.body, agent.position, agent.heading,
                agent.resumeToken));
        broadcast(new AgentAddedMessage(tick, agent.state()), Audience.VIEWERS);
        listeners.forEach(l -> l.agentJoined(agent.name));
    }

    /** A new resume token: 128 random bits, in hex. */
    private String newToken() {
        byte[] bytes = new byte[16];
        secrets.nextBytes(bytes);
        return HexFormat.of().formatHex(bytes);
    }

    /** Compares in time independent of where the tokens differ, so timing does not reveal a token. */
    private static boolean tokenMatches(String expected, String offered) {
        return offered != null && MessageDigest.isEqual(expected.getBytes(java.nio.charset.StandardCharsets.UTF_8),
                offered.getBytes(java.nio.charset.StandardCharsets.UTF_8));
    }

    /**
     * The draws that place an agent and turn it at first, from the game's seed and the agent's name
     * alone: an agent starts where it started in any other game of the seed, whichever joined first.
     */
    private java.util.random.RandomGenerator placing(String name) {
        return new java.util.SplittableRandom(seed ^ (name.hashCode() * 0x9E3779B97F4A7C15L) ^ 0x5DEECE66DL);
    }

    /** A free place for a body of this radius: the placement's, or drawn from the game's seed and the name. */
    private Vec3 placeFor(String name, double radius, java.util.random.RandomGenerator draws) {
        Vec3 wanted = placement.placeFor(name, radius);
        if (wanted != null && world.checkPlace(wanted.onGround(), radius).isFree()
                && walking.clearOfAgents(wanted, radius, null)) {
            return Vec3.ground(wanted.x(), wanted.z());
        }
        for (int attempt = 0; attempt < 500; attempt++) {
            Vec3 candidate = world.randomFreePoint(draws, radius + 0.1);
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
        continueWhenAllBack = false; // whoever pauses or resumes now decides
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
        continueWhenAllBack = false;
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
        recorder = Recorder.NONE;
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
        recorder.sent(tick, time, Audience.CLIENT, session.id(), withoutSecrets(message));
        session.send(message);
    }

    /** Recordings may be shared: they keep no resume token. */
    private static io.orchard.protocol.message.Message withoutSecrets(io.orchard.protocol.message.Message message) {
        if (message instanceof RegisteredMessage r && r.resumeToken() != null) {
            return new RegisteredMessage(r.seq(), r.agent(), r.body(), r.position(), r.heading(), null);
        }
        if (message instanceof RegisterMessage r && r.resumeToken() != null) {
            return new RegisterMessage(r.seq(), r.name(), r.body(), r.model(), null);
        }
        return message;
    }

    void broadcast(ServerMessage message, Audience audience) {
        recorder.sent(tick, time, audience, 0, message);
        Map<Long, ClientSession> to = switch (audience) {
            case ALL -> sessions;
            case VIEWERS -> viewers;
            case AGENTS -> agentClients;
            case CLIENT -> Map.of();
        };
        if (to.isEmpty()) {
            return;
        }
        EncodedLine line = EncodedLine.of(CODEC, message);
        for (ClientSession session : to.values()) {
            session.send(line);
        }
    }

    /**
     * Client by client, each client's events in the order it sent them: first the server's own
     * tasks and the clients without an agent, in the order they connected; then the clients of
     * agents, in the order of their agents' names rather than of their connections, so that a
     * lockstep game of a seed plays out the same however the clients' threads raced to connect.
     */
    private List<Event> inClientOrder(List<Event> events) {
        Map<Long, List<Event>> bySession = new HashMap<>();
        for (Event event : events) {
            bySession.computeIfAbsent(event.session() == null ? -1L : event.session().id(),
                    id -> new ArrayList<>(2)).add(event);
        }
        if (bySession.size() < 2) {
            return events;
        }
        List<Event> named = new ArrayList<>(events.size());
        for (Agent agent : agents.values()) { // by name
            List<Event> own = bySession.remove(agent.owner.id());
            if (own != null) {
                named.addAll(own);
            }
        }
        List<Long> unnamed = new ArrayList<>(bySession.keySet());
        unnamed.sort(null);
        List<Event> ordered = new ArrayList<>(events.size());
        for (Long id : unnamed) {
            ordered.addAll(bySession.get(id));
        }
        ordered.addAll(named);
        return ordered;
    }

    private void flushAll() {
        sessions.values().forEach(ClientSession::flush);
        recorder.flush();
    }

    // ---- checkpoints ---------------------------------------------------------------------------

    /**
     * Takes a checkpoint at the end of the current tick (at once while no ticks pass) and gives it
     * to {@code to} on the simulation's thread. Safe from any thread.
     */
    public void checkpointAtTickEnd(Consumer<Checkpoint> to) {
        execute(() -> checkpointRequests.add(to));
    }

    /**
     * Gives {@code to} a checkpoint after every tick in which the scores changed and when the game
     * ends, so that nothing collected is lost to a crash. Call before the simulation's thread starts.
     */
    public void checkpointWhenScored(Consumer<Checkpoint> to) {
        this.onScore = to;
    }

    private void takeCheckpoints(boolean scored) {
        boolean forScore = scored && onScore != null;
        if (checkpointRequests.isEmpty() && !forScore) {
            return;
        }
        Checkpoint checkpoint = checkpoint();
        if (forScore) {
            onScore.accept(checkpoint);
            overSaved = phase == Phase.OVER;
        }
        checkpointRequests.forEach(request -> request.accept(checkpoint));
        checkpointRequests.clear();
    }

    /** The whole game as it is now. Call on the simulation's thread (or between steps, in a test). */
    public Checkpoint checkpoint() {
        List<Checkpoint.SavedAgent> saved = new ArrayList<>(waiting.values());
        agents.values().forEach(agent -> saved.add(saved(agent)));
        return new Checkpoint(Checkpoint.FORMAT, seed, config.tickRate(), config.clock(), config.timeLimit(),
                config.waitFor(), phase.name().toLowerCase(java.util.Locale.ROOT), tick, time, fruitAtStart,
                world.toScenario(), saved, scores.ranking());
    }

    private static Checkpoint.SavedAgent saved(Agent agent) {
        return new Checkpoint.SavedAgent(agent.name, agent.body, agent.model, agent.position, agent.heading,
                List.copyOf(agent.joints), List.copyOf(agent.timeSensors), agent.resumeToken);
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
        tick = checkpoint.tick();
        time = checkpoint.time();
        fruitAtStart = checkpoint.fruitAtStart();
        checkpoint.scores().forEach(scores::restore);
        for (Checkpoint.SavedAgent agent : checkpoint.agents()) {
            waiting.put(agent.name(), agent);
        }
        phase = checkpoint.gamePhase();
        if (phase == Phase.RUNNING) {
            phase = waiting.isEmpty() ? Phase.RUNNING : Phase.PAUSED;
            continueWhenAllBack = true;
        }
        overSaved = phase == Phase.OVER;
    }

    /** Names of the agents of a restored game that are still waiting for their controllers. */
    public List<String> waitingAgents() {
        return List.copyOf(waiting.keySet());
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
