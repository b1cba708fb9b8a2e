package io.orchard.cluster.game;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.LineKey.Step;
import io.orchard.cluster.order.Merge;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.KeepAliveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.FruitKind;
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
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;

/**
 * A game whose world is cut into parcels, each simulated on its own ({@link Parcel}), in one JVM:
 * the same game the single server's {@link Simulation} plays, recorded and sent byte for byte as it
 * does, with the parcels' work in between. It steps as a simulation does ({@link #beginTick()},
 * {@link #endTick()}, {@link #applyNow()}); one thread owns it, others hand it events through its
 * {@link Inbox} methods.
 *
 * <p>Before the game starts, a plain simulation (the lobby) takes the registrations and setups and
 * settles where agents stand, exactly as one server does; at the start its agents go to the parcels
 * their places lie in. From then on every tick runs in the steps of docs/scaling.md, and what the
 * parcels say is merged by key ({@link Merge}).
 *
 * <p>Not yet: agents that join, leave or come back once the game runs, viewers that connect to a
 * game under way, pausing, and lockstep turns (the caller ends each tick).
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
    private final BlockingQueue<Event> inbox = new LinkedBlockingQueue<>();
    private final Map<ParcelId, Parcel> parcels = new TreeMap<>();
    /** Every agent's controller, by the agent's name: the order in which clients' messages apply. */
    private final Map<String, ClientSession> owners = new TreeMap<>();
    private final Map<String, ParcelId> where = new HashMap<>();
    private final Map<Long, String> labels = new HashMap<>();
    private final Map<String, ParcelId> fruitParcels = new HashMap<>();
    private final Map<String, Vec3> fruitPlaces = new HashMap<>();
    private final Scoreboard scores = new Scoreboard();
    private final KeyedLines own = new KeyedLines();
    private final Counters counts = new Counters();
    private final List<String> taken = new ArrayList<>();
    private boolean split;
    private Phase phase = Phase.WAITING;
    private long tick;
    private double time;
    private int fruitLeft;

    /**
     * A game of {@code world}, made from {@code seed}, cut into parcels of {@code parcelSize} units,
     * recorded to {@code recorder}. The parcels' halos reach as far as the longest sight
     * {@code config} allows.
     */
    public SplitGame(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                     List<GameListener> listeners, double parcelSize) {
        this(world, config, seed, serverVersion, recorder, listeners, parcelSize, (name, radius) -> null);
    }

    /** As the other constructor, asking {@code placement} first where each agent stands at first. */
    public SplitGame(World world, SimulationConfig config, long seed, String serverVersion, Recorder recorder,
                     List<GameListener> listeners, double parcelSize, Placement placement) {
        this.world = world;
        this.config = config;
        this.listeners = List.copyOf(listeners);
        this.merge = new Merge(recorder);
        double halo = Math.max(config.bodyLimits().maxRange(), PartialSimulation.touchingReach(config));
        this.grid = new ParcelGrid(world.bounds(), parcelSize, halo);
        this.lobby = new Simulation(world, config, seed, serverVersion, recorder, listeners, placement);
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
        GameListener taking = new GameListener() {
            @Override
            public void fruitEaten(String agent, String fruit, FruitKind kind, double at) {
                taken(agent, fruit, kind, at);
            }
        };
        for (ParcelId id : grid.all()) {
            parcels.put(id, new Parcel(id, world.withOwnFruit(), config, taking, elsewhere(id)));
        }
        for (Driven driven : lobby.handOver()) {
            String name = driven.agent().name();
            owners.put(name, driven.owner());
            labels.put(driven.owner().id(), driven.label());
            ParcelId home = grid.of(driven.agent().position());
            where.put(name, home);
            parcels.get(home).own(driven);
        }
        refreshGhosts();
    }

    /** Asks the parcels along a walker's path for their first contact, when the path leaves the halo. */
    private PartialSimulation.Elsewhere elsewhere(ParcelId asking) {
        return (walker, from, to, radius) -> {
            double margin = radius + config.bodyLimits().maxRadius();
            double minX = Math.min(from.x(), to.x()) - margin;
            double minZ = Math.min(from.z(), to.z()) - margin;
            double maxX = Math.max(from.x(), to.x()) + margin;
            double maxZ = Math.max(from.z(), to.z()) + margin;
            if (grid.holds(asking, minX, minZ, maxX, maxZ)) {
                return null;
            }
            counts.pathsBeyondHalo++;
            FirstContact first = null;
            for (ParcelId id : grid.meeting(minX, minZ, maxX, maxZ)) {
                FirstContact contact = id.equals(asking) ? null : parcels.get(id).firstAlong(walker, from, to, radius);
                if (contact != null && contact.before(first)) {
                    first = contact;
                }
            }
            return first;
        };
    }

    /** The first half of a tick: the clock and the perceptions asked for. */
    public void beginTick() {
        if (phase != Phase.RUNNING) {
            return;
        }
        own.cause(LineKey.of(tick, Step.TICK));
        own.sent(tick, time, Audience.ALL, null, new TickMessage(tick, time));
        List<KeyedLine> lines = new ArrayList<>(own.take());
        for (Parcel parcel : parcels.values()) {
            parcel.perceive(tick, time);
            List<KeyedLine> said = parcel.takeLines();
            countSightings(said);
            lines.addAll(said);
        }
        merge.write(lines);
        merge.flush();
    }

    /** The second half of a tick: apply what clients sent, grasp, walk, hand over, check the end. */
    public void endTick() {
        if (phase != Phase.RUNNING) {
            applyNow();
            return;
        }
        List<Event> events = new ArrayList<>();
        inbox.drainTo(events);
        for (Map.Entry<LineKey, Event> applied : inClientOrder(events).entrySet()) {
            apply(applied.getKey(), applied.getValue());
        }
        List<KeyedLine> lines = new ArrayList<>(own.take());
        List<Parcel.KeyedClaim> claims = new ArrayList<>();
        for (Parcel parcel : parcels.values()) {
            claims.addAll(parcel.takeClaims());
            lines.addAll(parcel.takeLines());
        }
        refreshGhosts(); // as the tick's actions left them: facing and walking
        boolean collected = grasp(claims, lines);
        double next = (tick + 1) * config.tickSeconds();
        walk(next, lines);
        handOver();
        refreshGhosts();
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

    private void apply(LineKey key, Event event) {
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
            ClientSession owner = owners.get(about.agent());
            if (session.role() != Role.AGENT) {
                refuse(session, message, ErrorCode.WRONG_ROLE, "a viewer cannot drive agents");
            } else if (owner == null) {
                refuse(session, message, ErrorCode.UNKNOWN_AGENT, "no agent named '" + about.agent() + "' in the world");
            } else if (owner.id() != session.id()) {
                refuse(session, message, ErrorCode.NOT_YOUR_AGENT, "agent '" + about.agent()
                        + "' belongs to another connection");
            } else {
                parcels.get(where.get(about.agent())).act(key, tick, time, session, message);
            }
        } else if (message instanceof InstructionMessage instruction) {
            own.accepted(tick, time, label(session), message);
            ClientSession owner = owners.get(instruction.agent());
            if (owner == null) {
                say(session, new ErrorMessage(message.seq(), ErrorCode.UNKNOWN_AGENT, "no agent named '"
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
        say(session, new ErrorMessage(message.seq(), code, why));
    }

    /** Sends a message to one client, in its place among the coordinator's lines. */
    private void say(ClientSession to, ServerMessage message) {
        own.sent(tick, time, Audience.CLIENT, label(to), message);
        new io.orchard.cluster.order.ProxySession(to, own).send(message);
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
        claims.sort((a, b) -> a.key().compareTo(b.key()));
        Map<String, LineKey> firstClaims = new HashMap<>();
        Map<ParcelId, Parcel> deciding = new LinkedHashMap<>();
        for (Parcel.KeyedClaim keyed : claims) {
            String fruit = keyed.claim().message().fruit();
            String agent = keyed.claim().agent().name();
            ParcelId at = fruitParcels.getOrDefault(fruit, where.get(agent));
            if (!at.equals(where.get(agent))) {
                counts.graspsAcrossBorders++;
            }
            firstClaims.putIfAbsent(fruit, keyed.key().in(Step.GRASP));
            ClientSession owner = owners.get(agent);
            Parcel parcel = parcels.get(at);
            parcel.claim(keyed.claim(), owner, label(owner));
            deciding.put(at, parcel);
        }
        taken.clear();
        for (Parcel parcel : deciding.values()) {
            parcel.resolveGrasps(tick, time, firstClaims::get);
            lines.addAll(parcel.takeLines());
        }
        for (String fruit : taken) {
            Vec3 place = fruitPlaces.get(fruit);
            for (ParcelId id : grid.seeing(place.x(), place.z())) {
                parcels.get(id).fruitTaken(fruit);
            }
        }
        return !taken.isEmpty();
    }

    private void taken(String agent, String fruit, FruitKind kind, double at) {
        scores.collect(agent, kind);
        fruitLeft--;
        taken.add(fruit);
        listeners.forEach(l -> l.fruitEaten(agent, fruit, kind, at));
    }

    /** Walks every agent to {@code next}: parcel by parcel, and the sets across borders together. */
    private void walk(double next, List<KeyedLine> lines) {
        List<AgentHandover> together = new ArrayList<>();
        for (Parcel parcel : parcels.values()) {
            for (String name : parcel.walk(tick, next)) {
                together.add(parcel.state(name));
            }
            lines.addAll(parcel.takeLines());
        }
        if (!together.isEmpty()) {
            counts.walkedTogether += together.size();
            own.byAgent(tick, Step.WALK);
            for (AgentHandover walked : PartialSimulation.walkTogether(together, config, tick, next, own)) {
                parcels.get(where.get(walked.name())).walked(walked);
            }
        }
    }

    /** Agents that walked out of their parcel's square go to the parcel they walked into. */
    private void handOver() {
        for (Parcel parcel : parcels.values()) {
            for (AgentHandover agent : parcel.owned()) {
                ParcelId into = grid.of(agent.position());
                if (!into.equals(parcel.id())) {
                    parcel.release(agent.name());
                    ClientSession owner = owners.get(agent.name());
                    parcels.get(into).own(new Driven(agent, owner, label(owner)));
                    where.put(agent.name(), into);
                    counts.handOvers++;
                }
            }
        }
    }

    /** Every parcel's ghosts anew: the agents of other parcels within its halo, as they are now. */
    private void refreshGhosts() {
        parcels.values().forEach(Parcel::forgetGhosts);
        for (Parcel parcel : parcels.values()) {
            for (AgentHandover agent : parcel.owned()) {
                ClientSession owner = owners.get(agent.name());
                Driven driven = new Driven(agent, owner, label(owner));
                for (ParcelId id : grid.seeing(agent.position().x(), agent.position().z())) {
                    if (!id.equals(parcel.id())) {
                        parcels.get(id).ghost(driven);
                    }
                }
            }
        }
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
