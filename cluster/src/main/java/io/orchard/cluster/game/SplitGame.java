package io.orchard.cluster.game;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.LineKey.Step;
import io.orchard.cluster.order.Merge;
import io.orchard.cluster.order.ProxySession;
import io.orchard.cluster.order.SessionRef;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.KeepAliveMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.Inbox;
import io.orchard.server.sim.PartialSimulation;
import io.orchard.server.sim.PartialSimulation.Driven;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.sim.Scoreboard;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.Fruit;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.time.Duration;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

/**
 * A game whose world is cut into parcels, each simulated on its own ({@link Parcel}): the same game
 * the single server's {@link Simulation} plays, recorded and sent byte for byte as it does, with the
 * parcels' work in between. It steps as a simulation does ({@link #beginTick()}, {@link #endTick()},
 * {@link #applyNow()}); one thread owns it, others hand it events through its {@link Inbox} methods.
 * Where the parcels are, in this JVM or on the nodes of a cluster, is the {@link Parcels}' affair.
 *
 * <p>Before the game starts, a plain simulation (the lobby) takes the registrations and setups and
 * settles where agents stand, exactly as one server does; at the start its agents go to the parcels
 * their places lie in. From then on every tick runs in the steps of docs/scaling.md, and what the
 * parcels say is merged by key ({@link Merge}).
 *
 * <p>In lockstep, its owner waits for the agents' turns ({@link #awaitTurns}) between the two halves
 * of a tick; a turn missed is not yet recorded as the single server records it. Not yet: agents
 * that join, leave or come back once the game runs, viewers that connect to a game under way, and
 * pausing.
 */
public final class SplitGame implements Inbox {

    /** What a client did, queued for the game's thread. */
    private record Event(ClientSession session, ClientMessage message, boolean connected, boolean gone) {}

    private final World world;
    private final SimulationConfig config;
    private final List<GameListener> listeners;
    private final Simulation lobby;
    private final Merge merge;
    private final ParcelGrid grid;
    private final Function<ParcelGrid, Parcels> parcelsOf;
    private final BlockingQueue<Event> inbox = new LinkedBlockingQueue<>();
    /** Events taken from the inbox while waiting for turns, applied at the end of the tick. */
    private final List<Event> pending = new ArrayList<>();
    private Parcels parcels;
    /** Every agent's controller, by the agent's name: the order in which clients' messages apply. */
    private final Map<String, SessionRef> owners = new TreeMap<>();
    /** Every agent as the parcels last said it was. */
    private final Map<String, AgentHandover> states = new TreeMap<>();
    private final Map<String, ParcelId> where = new HashMap<>();
    private final Map<Long, String> labels = new HashMap<>();
    private final Map<String, ParcelId> fruitParcels = new HashMap<>();
    private final Map<String, Vec3> fruitPlaces = new HashMap<>();
    private final Scoreboard scores = new Scoreboard();
    private final KeyedLines own = new KeyedLines();
    private final Counters counts = new Counters();
    private boolean split;
    private Phase phase = Phase.WAITING;
    private long tick;
    private double time;
    private int fruitLeft;

    /**
     * A game of {@code world}, made from {@code seed}, cut into parcels of {@code parcelSize} units
     * in this JVM, recorded to {@code recorder}.
     */
    public SplitGame(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                     List<GameListener> listeners, double parcelSize) {
        this(world, config, seed, serverVersion, recorder, listeners, parcelSize, (name, radius) -> null,
                grid -> new LocalParcels(grid, world, config));
    }

    /**
     * A game of {@code world}, made from {@code seed}, cut into parcels of {@code parcelSize} units
     * that {@code parcelsOf} makes for the grid, recorded to {@code recorder}; {@code placement} is
     * asked first where each agent stands at first. The parcels' halos reach as far as the longest
     * sight {@code config} allows.
     */
    public SplitGame(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                     List<GameListener> listeners, double parcelSize, Placement placement,
                     Function<ParcelGrid, Parcels> parcelsOf) {
        this.world = world;
        this.config = config;
        this.listeners = List.copyOf(listeners);
        this.merge = new Merge(recorder);
        this.grid = grid(world, config, parcelSize);
        this.parcelsOf = parcelsOf;
        this.lobby = new Simulation(world, config, seed, serverVersion, recorder, listeners, placement);
    }

    /** The parcels of a game of {@code world} in parcels of {@code size}, their halos as long as sight may be. */
    public static ParcelGrid grid(World world, SimulationConfig config, double size) {
        return new ParcelGrid(world.bounds(), size, Math.max(config.bodyLimits().maxRange(),
                PartialSimulation.touchingReach(config)));
    }

    // ---- Inbox: any thread -------------------------------------------------------------------

    @Override
    public void connected(ClientSession session) {
        inbox.add(new Event(session, null, true, false));
    }

    @Override
    public void received(ClientSession session, ClientMessage message) {
        inbox.add(new Event(session, message, false, false));
    }

    @Override
    public void disconnected(ClientSession session, String reason) {
        inbox.add(new Event(session, null, false, true));
    }

    @Override
    public WelcomeMessage welcome(long seq, Role role, int protocolVersion) {
        return lobby.welcome(seq, role, protocolVersion);
    }

    // ---- the game's thread ---------------------------------------------------------------------

    /** Applies what clients sent while no ticks pass; the lobby's until the game starts. */
    public void applyNow() {
        List<Event> events = new ArrayList<>();
        inbox.drainTo(events);
        if (split) {
            events.forEach(this::outOfTick);
            return;
        }
        for (Event event : events) {
            if (event.connected()) {
                merge.join(event.session());
                lobby.connected(event.session());
            } else if (event.gone()) {
                merge.leave(event.session());
                lobby.disconnected(event.session(), "connection closed");
            } else {
                lobby.received(event.session(), event.message());
            }
        }
        lobby.applyNow();
        if (lobby.phase() == Phase.RUNNING) {
            split();
        }
    }

    /** The game started in the lobby: its agents go to their parcels. */
    private void split() {
        split = true;
        phase = Phase.RUNNING;
        tick = lobby.tick();
        time = lobby.time();
        lobby.ranking().forEach(scores::restore);
        for (Fruit fruit : world.fruit()) {
            fruitParcels.put(fruit.id(), grid.of(fruit.position()));
            fruitPlaces.put(fruit.id(), fruit.position());
        }
        fruitLeft = world.fruitCount();
        parcels = parcelsOf.apply(grid);
        Map<ParcelId, List<OwnedAgent>> homes = new TreeMap<>();
        for (Driven driven : lobby.handOver()) {
            String name = driven.agent().name();
            owners.put(name, SessionRef.of(driven.owner()));
            labels.put(driven.owner().id(), driven.label());
            // Parcels simulate agents; their models are for viewers, and may be megabytes each.
            AgentHandover agent = driven.agent().withoutModel();
            states.put(name, agent);
            ParcelId home = grid.of(agent.position());
            where.put(name, home);
            homes.computeIfAbsent(home, id -> new ArrayList<>()).add(owned(agent));
        }
        parcels.own(homes);
    }

    private OwnedAgent owned(AgentHandover agent) {
        SessionRef owner = owners.get(agent.name());
        return new OwnedAgent(agent, owner, labels.get(owner.id()));
    }

    /**
     * In lockstep: waits until the client of every agent has ended its turn of the running tick, or
     * {@code deadline} of wall-clock time has passed; what they send meanwhile counts in this tick.
     *
     * @return whether every turn was ended in time
     */
    public boolean awaitTurns(Duration deadline) throws InterruptedException {
        Set<Long> waiting = new HashSet<>();
        owners.values().forEach(owner -> waiting.add(owner.id()));
        pending.forEach(event -> ended(event, waiting));
        long end = System.nanoTime() + deadline.toNanos();
        while (!waiting.isEmpty()) {
            long left = end - System.nanoTime();
            if (left <= 0) {
                return false;
            }
            Event event = inbox.poll(left, TimeUnit.NANOSECONDS);
            if (event != null) {
                pending.add(event);
                ended(event, waiting);
            }
        }
        return true;
    }

    /** Takes the event's client off {@code waiting} when it ended its turn of this tick or left. */
    private void ended(Event event, Set<Long> waiting) {
        if (event.gone() || event.message() instanceof EndTurnMessage end && end.tick() >= tick) {
            waiting.remove(event.session().id());
        }
    }

    /** The first half of a tick: the clock and the perceptions asked for. */
    public void beginTick() {
        if (phase != Phase.RUNNING) {
            return;
        }
        own.cause(LineKey.of(tick, Step.TICK));
        own.sent(tick, time, Audience.ALL, null, new TickMessage(tick, time));
        List<KeyedLine> lines = new ArrayList<>(own.take());
        List<KeyedLine> perceived = parcels.perceive(tick, time, ghosts());
        countSightings(perceived);
        lines.addAll(perceived);
        merge.write(lines);
        merge.flush();
    }

    /** The second half of a tick: apply what clients sent, grasp, walk, hand over, check the end. */
    public void endTick() {
        if (phase != Phase.RUNNING) {
            applyNow();
            return;
        }
        List<Event> events = new ArrayList<>(pending);
        pending.clear();
        inbox.drainTo(events);
        Map<ParcelId, List<Parcel.Act>> acts = new TreeMap<>();
        for (Map.Entry<LineKey, Event> applied : inClientOrder(events).entrySet()) {
            apply(applied.getKey(), applied.getValue(), acts);
        }
        List<KeyedLine> lines = new ArrayList<>(own.take());
        Parcels.Applied applied = parcels.apply(tick, time, acts, pathsBeyondHalos(acts));
        lines.addAll(applied.lines());
        applied.owned().forEach(agent -> states.put(agent.name(), agent)); // facing and walking as the actions left them
        boolean collected = grasp(applied.claims(), lines);
        double next = (tick + 1) * config.tickSeconds();
        walk(next, lines);
        handOver();
        if (collected) {
            own.cause(LineKey.of(tick, Step.SCORE));
            own.sent(tick, next, Audience.ALL, null, new ScoreUpdateMessage(tick, scores.ranking()));
        }
        lines.addAll(own.take());
        merge.write(lines);
        long ended = tick;
        tick = ended + 1;
        time = next;
        String over = fruitLeft == 0 ? "all fruit collected"
                : time >= config.timeLimit() - 1e-9 ? "time limit reached" : null;
        if (over != null) {
            end(ended, over);
        }
        listeners.forEach(l -> l.tickEnded(ended, next));
        merge.flush();
    }

    /** Each message of the tick with its place: client by client in the order of their agents' names. */
    private Map<LineKey, Event> inClientOrder(List<Event> events) {
        Map<Long, String> rank = new HashMap<>();
        owners.forEach((name, session) -> rank.putIfAbsent(session.id(), name));
        Map<Long, Integer> counted = new HashMap<>();
        Map<LineKey, Event> ordered = new TreeMap<>();
        for (Event event : events) {
            long session = event.session().id();
            int index = counted.merge(session, 1, Integer::sum) - 1;
            String name = rank.get(session);
            ordered.put(name != null ? new LineKey(tick, Step.APPLY, name, 0, index, 0)
                    : new LineKey(tick, Step.APPLY, "", session, index, 0), event);
        }
        return ordered;
    }

    /** Takes one event of the tick: a message about an own agent goes to its parcel, the rest is answered here. */
    private void apply(LineKey key, Event event, Map<ParcelId, List<Parcel.Act>> acts) {
        ClientSession session = event.session();
        if (event.connected() || event.gone()) {
            outOfTick(event);
            return;
        }
        ClientMessage message = event.message();
        if (message instanceof KeepAliveMessage) {
            return; // it says only that the client is there
        }
        own.cause(key);
        if (message instanceof EndTurnMessage) {
            own.accepted(tick, time, label(session), message);
        } else if (message instanceof AgentMessage about) {
            SessionRef owner = owners.get(about.agent());
            if (session.role() != Role.AGENT) {
                refuse(session, message, ErrorCode.WRONG_ROLE, "a viewer cannot drive agents");
            } else if (owner == null) {
                refuse(session, message, ErrorCode.UNKNOWN_AGENT, "no agent named '" + about.agent() + "' in the world");
            } else if (owner.id() != session.id()) {
                refuse(session, message, ErrorCode.NOT_YOUR_AGENT, "agent '" + about.agent()
                        + "' belongs to another connection");
            } else {
                acts.computeIfAbsent(where.get(about.agent()), id -> new ArrayList<>())
                        .add(new Parcel.Act(key, SessionRef.of(session), message));
            }
        } else if (message instanceof InstructionMessage instruction) {
            own.accepted(tick, time, label(session), message);
            SessionRef owner = owners.get(instruction.agent());
            if (owner == null) {
                say(SessionRef.of(session), new ErrorMessage(message.seq(), ErrorCode.UNKNOWN_AGENT, "no agent named '"
                        + instruction.agent() + "' in the world"));
            } else {
                say(owner, instruction);
            }
        } else {
            refuse(session, message, ErrorCode.INVALID_VALUE, "this game's world is cut into parcels, which take "
                    + "registrations and game controls only before the game starts");
        }
    }

    private void refuse(ClientSession session, ClientMessage message, ErrorCode code, String why) {
        own.accepted(tick, time, label(session), message);
        say(SessionRef.of(session), new ErrorMessage(message.seq(), code, why));
    }

    /** Sends a message to one client, in its place among the coordinator's lines. */
    private void say(SessionRef to, ServerMessage message) {
        own.sent(tick, time, Audience.CLIENT, labels.getOrDefault(to.id(), "agent"), message);
        new ProxySession(to, own).send(message);
    }

    /**
     * The first contacts on the paths of this tick's moves that leave their parcel's halo, from the
     * parcels along them; every agent stands where it stood at the start of the tick until it walks.
     */
    private Map<PathQuery, FirstContact> pathsBeyondHalos(Map<ParcelId, List<Parcel.Act>> acts) {
        Map<ParcelId, List<PathQuery>> asks = new TreeMap<>();
        List<PathQuery> beyond = new ArrayList<>();
        double maxRadius = config.bodyLimits().maxRadius();
        acts.forEach((home, own) -> {
            for (Parcel.Act act : own) {
                if (act.message() instanceof MoveMessage move) {
                    AgentHandover walker = states.get(move.agent());
                    PathQuery path = new PathQuery(walker.name(), walker.position(),
                            Vec3.ground(move.to().x(), move.to().z()), walker.body().radius());
                    if (Parcel.leavesHalo(grid, home, path, maxRadius)) {
                        counts.pathsBeyondHalo++;
                        beyond.add(path);
                        for (ParcelId id : grid.along(path, maxRadius)) {
                            if (!id.equals(home)) {
                                asks.computeIfAbsent(id, i -> new ArrayList<>()).add(path);
                            }
                        }
                    }
                }
            }
        });
        Map<PathQuery, FirstContact> first = new HashMap<>(asks.isEmpty() ? Map.of() : parcels.firstAlong(asks));
        beyond.forEach(path -> first.putIfAbsent(path, null)); // none asked: the path meets no other parcel
        return first;
    }

    /** What comes while no tick passes, or what the parcels do not take yet: a client that comes or goes. */
    private void outOfTick(Event event) {
        if (event.connected()) {
            merge.join(event.session());
        } else if (event.gone()) {
            merge.leave(event.session());
        }
    }

    private String label(ClientSession session) {
        return session.role() == Role.VIEWER ? "viewer" : labels.getOrDefault(session.id(), "agent");
    }

    /** Every grasp of the tick to the parcel of its fruit, in order; true when a fruit was taken. */
    private boolean grasp(List<Parcel.KeyedClaim> claims, List<KeyedLine> lines) {
        List<Parcel.KeyedClaim> ordered = new ArrayList<>(claims);
        ordered.sort((a, b) -> a.key().compareTo(b.key()));
        Map<String, LineKey> firstClaims = new HashMap<>();
        Map<ParcelId, List<Parcel.ClaimOf>> deciding = new TreeMap<>();
        for (Parcel.KeyedClaim keyed : ordered) {
            String fruit = keyed.claim().message().fruit();
            String agent = keyed.claim().agent().name();
            ParcelId at = fruitParcels.getOrDefault(fruit, where.get(agent));
            if (!at.equals(where.get(agent))) {
                counts.graspsAcrossBorders++;
            }
            firstClaims.putIfAbsent(fruit, keyed.key().in(Step.GRASP));
            SessionRef owner = owners.get(agent);
            deciding.computeIfAbsent(at, id -> new ArrayList<>())
                    .add(new Parcel.ClaimOf(keyed.claim(), owner, labels.get(owner.id())));
        }
        if (deciding.isEmpty()) {
            return false;
        }
        Parcels.Grasped grasped = parcels.grasp(tick, time, deciding, firstClaims);
        lines.addAll(grasped.lines());
        Map<ParcelId, List<String>> seen = new TreeMap<>();
        List<Parcel.Taken> taken = new ArrayList<>(grasped.taken());
        taken.sort((a, b) -> firstClaims.get(a.fruit()).compareTo(firstClaims.get(b.fruit())));
        for (Parcel.Taken fruit : taken) {
            scores.collect(fruit.agent(), fruit.kind());
            fruitLeft--;
            listeners.forEach(l -> l.fruitEaten(fruit.agent(), fruit.fruit(), fruit.kind(), fruit.time()));
            Vec3 place = fruitPlaces.get(fruit.fruit());
            for (ParcelId id : grid.seeing(place.x(), place.z())) {
                seen.computeIfAbsent(id, i -> new ArrayList<>()).add(fruit.fruit());
            }
        }
        parcels.fruitTaken(seen);
        return !taken.isEmpty();
    }

    /** Walks every agent to {@code next}: parcel by parcel, and the sets across borders together. */
    private void walk(double next, List<KeyedLine> lines) {
        Parcels.Walked walked = parcels.walk(tick, next, ghosts());
        lines.addAll(walked.lines());
        walked.owned().forEach(agent -> states.put(agent.name(), agent));
        if (!walked.left().isEmpty()) {
            counts.walkedTogether += walked.left().size();
            own.byAgent(tick, Step.WALK);
            Map<ParcelId, List<AgentHandover>> back = new TreeMap<>();
            for (AgentHandover agent : PartialSimulation.walkTogether(walked.left(), config, tick, next, own)) {
                back.computeIfAbsent(where.get(agent.name()), id -> new ArrayList<>()).add(agent);
                states.put(agent.name(), agent);
            }
            parcels.walked(back);
        }
    }

    /** Agents that walked out of their parcel's square go to the parcel they walked into. */
    private void handOver() {
        Map<ParcelId, List<String>> leaving = new TreeMap<>();
        Map<ParcelId, List<OwnedAgent>> arriving = new TreeMap<>();
        for (AgentHandover agent : states.values()) {
            ParcelId from = where.get(agent.name());
            ParcelId into = grid.of(agent.position());
            if (!into.equals(from)) {
                leaving.computeIfAbsent(from, id -> new ArrayList<>()).add(agent.name());
                arriving.computeIfAbsent(into, id -> new ArrayList<>()).add(owned(agent));
                where.put(agent.name(), into);
                counts.handOvers++;
            }
        }
        if (!leaving.isEmpty()) {
            parcels.release(leaving);
            parcels.own(arriving);
        }
    }

    /**
     * The ghosts of every parcel that has agents of its own: the agents of other parcels within its
     * halo, as they are now. Parcels without agents of their own need none.
     */
    private Map<ParcelId, List<OwnedAgent>> ghosts() {
        Set<ParcelId> holding = new HashSet<>(where.values());
        Map<ParcelId, List<OwnedAgent>> ghosts = new TreeMap<>();
        for (AgentHandover agent : states.values()) {
            ParcelId home = where.get(agent.name());
            OwnedAgent ghost = owned(agent);
            for (ParcelId id : grid.seeing(agent.position().x(), agent.position().z())) {
                if (!id.equals(home) && holding.contains(id)) {
                    ghosts.computeIfAbsent(id, i -> new ArrayList<>()).add(ghost);
                }
            }
        }
        return ghosts;
    }

    private void end(long ended, String reason) {
        phase = Phase.OVER;
        List<Score> ranking = scores.ranking();
        own.cause(LineKey.of(ended, Step.END));
        own.sent(tick, time, Audience.ALL, null, new GameOverMessage(tick, reason, ranking));
        merge.write(own.take());
        merge.flush();
        merge.stopRecording();
        listeners.forEach(l -> l.gameOver(reason, ranking));
    }

    /** Counts perceptions of an agent standing in another parcel than the perceiver's. */
    private void countSightings(List<KeyedLine> said) {
        for (KeyedLine line : said) {
            if (line.message() instanceof PerceptionMessage perception) {
                for (PerceivedAgent seen : perception.agents()) {
                    if (!where.get(seen.name()).equals(where.get(perception.agent()))) {
                        counts.sightingsAcrossBorders++;
                    }
                }
            }
        }
    }

    // ---- state ---------------------------------------------------------------------------------

    /** The settings the game runs with. */
    public SimulationConfig config() {
        return config;
    }

    /** The current phase. */
    public Phase phase() {
        return split ? phase : lobby.phase();
    }

    /** The tick that runs now. */
    public long tick() {
        return split ? tick : lobby.tick();
    }

    /** Every agent's score, best first. */
    public List<Score> ranking() {
        return split ? scores.ranking() : lobby.ranking();
    }

    /** How much crossed parcels' borders so far. */
    public SplitCounts counts() {
        return counts.copy();
    }

    /** Where each agent is now, by name: the parcel that owns it. */
    public Map<String, ParcelId> parcelsOfAgents() {
        return new TreeMap<>(where);
    }
}
