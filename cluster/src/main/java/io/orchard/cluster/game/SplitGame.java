package io.orchard.cluster.game;

import io.orchard.cluster.game.Applying.Event;
import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.LineKey.Step;
import io.orchard.cluster.order.Merge;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.Inbox;
import io.orchard.server.sim.PartialSimulation;
import io.orchard.server.sim.PartialSimulation.Driven;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.sim.Referee;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.Fruit;
import io.orchard.server.world.World;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
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
 * their places lie in, and the rest of the game (agents coming and going, scores, pauses, turns,
 * the end) to its {@link Referee}. From then on every tick runs in the steps of docs/scaling.md, and
 * what the parcels and the referee say is merged by key ({@link Merge}).
 *
 * <p>In lockstep, its owner waits for the agents' turns ({@link #awaitTurns}) between the two halves
 * of a tick; while the game waits, is paused or is over, it applies what comes as it comes
 * ({@link #applyNow()}).
 */
public final class SplitGame implements Inbox {

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
    /** Every client connected, by number, as the lobby and the referee know it. */
    private final Map<Long, Link> links = new HashMap<>();
    private final Roll roll = new Roll();
    private final Map<String, ParcelId> fruitParcels = new HashMap<>();
    private final Map<String, Vec3> fruitPlaces = new HashMap<>();
    /** The referee's lines, and what the game itself says. */
    private final KeyedLines own = new KeyedLines();
    private final Counters counts = new Counters();
    /** Null until the game starts. */
    private Referee referee;
    private Parcels parcels;
    private Applying applying;
    private long tick;
    private double time;
    /** How many events came while no tick passed: their keys. */
    private long idle;
    /** Who gets a checkpoint at the start, after every tick in which fruit was taken, and at the end. */
    private Consumer<Checkpoint> onScore;
    /** Who gets a checkpoint at the end of the tick under way (at once while no tick passes). */
    private final List<Consumer<Checkpoint>> atTickEnd = new ArrayList<>();
    private boolean overSaved;

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

    /**
     * Continues a saved game: its clock, scores and phase; its agents wait, out of the world, until
     * their controllers register them again with their tokens, as on a server resumed from the
     * checkpoint. Call before the game's thread starts, on a game made from the checkpoint's world
     * and settings.
     */
    public void restore(Checkpoint checkpoint) {
        lobby.restore(checkpoint);
    }

    /**
     * How long the name and score of an agent whose connection dropped stay its controller's, as
     * {@link Simulation#reserveDroppedNames}. Call before the game's thread starts.
     */
    public void reserveDroppedNames(Duration time) {
        lobby.reserveDroppedNames(time);
    }

    // ---- Inbox: any thread -------------------------------------------------------------------

    @Override
    public void connected(ClientSession session) {
        inbox.add(new Event(Event.Kind.CONNECTED, session, null, null, null));
    }

    @Override
    public void received(ClientSession session, ClientMessage message) {
        inbox.add(new Event(Event.Kind.RECEIVED, session, message, null, null));
    }

    @Override
    public void disconnected(ClientSession session, String reason) {
        inbox.add(new Event(Event.Kind.GONE, session, null, reason, null));
    }

    /** Runs {@code task} on the game's thread, before the clients' events of the same tick. */
    public void execute(Runnable task) {
        inbox.add(new Event(Event.Kind.TASK, null, null, null, task));
    }

    @Override
    public WelcomeMessage welcome(long seq, Role role, int protocolVersion) {
        return lobby.welcome(seq, role, protocolVersion);
    }

    // ---- the game's thread ---------------------------------------------------------------------

    /**
     * Waits up to {@code millis} for something to come while no ticks pass, then applies it and
     * whatever came with it ({@link #applyNow()}).
     */
    public void applyNext(long millis) throws InterruptedException {
        Event first = inbox.poll(millis, TimeUnit.MILLISECONDS);
        if (first != null) {
            pending.add(first);
        }
        applyNow();
    }

    /** Applies what clients sent while no ticks pass; the lobby's until the game starts. */
    public void applyNow() {
        List<Event> events = new ArrayList<>(pending);
        pending.clear();
        inbox.drainTo(events);
        if (referee != null) {
            if (!events.isEmpty()) {
                Map<LineKey, Event> ordered = new TreeMap<>();
                events.forEach(event -> ordered.put(new LineKey(tick, Step.IDLE, "", idle++, 0, 0), event));
                finish(applying.apply(tick, time, ordered).lines());
                saved(false);
            }
            return;
        }
        events.forEach(this::toLobby);
        lobby.applyNow();
        if (lobby.phase() != Phase.WAITING) {
            split();
        }
        saved(false);
    }

    private void toLobby(Event event) {
        ClientSession session = event.session();
        switch (event.kind()) {
            case TASK -> event.task().run();
            case CONNECTED -> {
                Link link = new Link(session);
                links.put(session.id(), link);
                merge.connected(session);
                merge.join(session);
                lobby.connected(link);
            }
            case GONE -> {
                Link link = links.remove(session.id());
                merge.leave(session);
                if (link != null) {
                    lobby.disconnected(link, event.reason());
                }
            }
            case RECEIVED -> {
                Link link = links.get(session.id());
                if (link != null) {
                    lobby.received(link, event.message());
                }
            }
        }
    }

    /** Whether a lockstep game has its agents and starts once their setup turns are over. */
    public boolean startDue() {
        return referee == null && lobby.startDue();
    }

    /** The start is due but some setup turns were not ended in time: they are missed, and the game starts. */
    public void startWithoutSetup() {
        if (referee == null) {
            lobby.startWithoutSetup();
            if (lobby.phase() != Phase.WAITING) {
                split();
            }
        }
    }

    /** The game started in the lobby: its agents go to their parcels, the rest to the referee. */
    private void split() {
        Set<String> fruitLeft = new HashSet<>();
        world.fruit().forEach(fruit -> fruitLeft.add(fruit.id()));
        parcels = parcelsOf.apply(grid);
        parcels.reset(fruitLeft); // first: should a parcel not answer, nothing has changed, and the start comes again
        referee = lobby.referee(own);
        links.values().forEach(link -> link.keyedInto(own));
        tick = referee.tick();
        time = referee.time();
        for (Fruit fruit : world.fruit()) {
            fruitParcels.put(fruit.id(), grid.of(fruit.position()));
            fruitPlaces.put(fruit.id(), fruit.position());
        }
        applying = new Applying(this, referee, roll, parcels, grid, config, own, merge, links, counts);
        Map<ParcelId, List<OwnedAgent>> homes = new TreeMap<>();
        for (Driven driven : referee.agents()) {
            // Parcels simulate agents; their models are for viewers, and may be megabytes each.
            AgentHandover agent = driven.agent().withoutModel();
            ParcelId home = grid.of(agent.position());
            roll.add(agent, (Link) driven.owner(), home);
            homes.computeIfAbsent(home, id -> new ArrayList<>()).add(owned(agent));
        }
        parcels.own(homes);
        if (referee.phase() == Phase.OVER) {
            merge.stopRecording(); // it ended before it started
        } else if (onScore != null) {
            onScore.accept(checkpoint()); // the saved game is this one's from its start
        }
    }

    /** An agent of the game with the client that drives it, as parcels hold it. */
    OwnedAgent owned(AgentHandover agent) {
        Link owner = roll.owner(agent.name());
        return new OwnedAgent(agent, owner.ref(), referee.label(owner));
    }

    /**
     * In lockstep: waits until the client of every agent has ended its turn of the running tick (but
     * the late ones, as one server does), or {@code deadline} of wall-clock time has passed; what they
     * send meanwhile counts in this tick. A game with no agent's client to wait for waits the deadline.
     *
     * @return whether every turn waited for was ended in time
     */
    public boolean awaitTurns(Duration deadline) throws InterruptedException {
        Set<Long> waiting = new HashSet<>(referee.turnsToWaitFor());
        boolean anyone = !waiting.isEmpty();
        pending.forEach(event -> ended(event, waiting));
        long end = System.nanoTime() + deadline.toNanos();
        while (!anyone || !waiting.isEmpty()) {
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
        if (event.kind() == Event.Kind.GONE || endsTurn(event)) {
            waiting.remove(event.session().id());
        }
    }

    private boolean endsTurn(Event event) {
        return event.message() instanceof EndTurnMessage end && end.tick() >= tick;
    }

    /** The first half of a tick: the clock and the perceptions asked for. */
    public void beginTick() {
        if (referee == null || referee.phase() != Phase.RUNNING) {
            return;
        }
        referee.at(tick, time);
        if (lockstep()) {
            referee.tickBegins();
        }
        own.cause(LineKey.of(tick, Step.TICK));
        referee.broadcast(new TickMessage(tick, time), Audience.ALL);
        List<KeyedLine> lines = new ArrayList<>(own.take());
        List<KeyedLine> perceived = parcels.perceive(tick, time, ghosts());
        countSightings(perceived);
        lines.addAll(perceived);
        merge.write(lines);
        merge.flush();
    }

    /**
     * The second half of a tick: apply what clients sent, record the turns missed, grasp, walk, hand
     * over, check the end. A pause that came during the tick takes effect once it is over.
     */
    public void endTick() {
        if (referee == null || referee.phase() != Phase.RUNNING) {
            applyNow();
            return;
        }
        List<Event> events = new ArrayList<>(pending);
        pending.clear();
        inbox.drainTo(events);
        Set<Long> endedTurns = new HashSet<>();
        events.stream().filter(this::endsTurn).forEach(event -> endedTurns.add(event.session().id()));
        referee.at(tick, time);
        Applying.Done applied = applying.apply(tick, time, inClientOrder(events));
        List<KeyedLine> lines = new ArrayList<>(applied.lines());
        Phase phase = referee.phase();
        if (phase == Phase.RUNNING || phase == Phase.PAUSED) {
            if (lockstep()) {
                own.byMissedTurn(tick);
                referee.turnsEnded(tick, endedTurns);
            }
            double next = (tick + 1) * config.tickSeconds();
            boolean collected = grasp(applied.claims(), lines);
            walk(next, lines);
            handOver();
            referee.at(tick, next);
            if (collected) {
                own.cause(LineKey.of(tick, Step.SCORE));
                referee.broadcast(new ScoreUpdateMessage(tick, referee.ranking()), Audience.ALL);
            }
            long ended = tick;
            tick = ended + 1;
            time = next;
            referee.at(tick, time);
            own.cause(LineKey.of(ended, Step.END));
            referee.checkOver();
            lines.addAll(own.take());
            listeners.forEach(l -> l.tickEnded(ended, next));
            finish(lines);
            saved(collected);
            return;
        }
        finish(lines);
        saved(false);
    }

    /** Writes what was said, in order; after the game's end nothing more is recorded. */
    private void finish(List<KeyedLine> lines) {
        merge.write(lines);
        if (referee.phase() == Phase.OVER) {
            merge.stopRecording();
        }
        merge.flush();
    }

    /** Each event of the tick with its place: client by client in the order of their agents' names. */
    private Map<LineKey, Event> inClientOrder(List<Event> events) {
        Map<Long, String> rank = roll.ranks();
        Map<Long, Integer> counted = new HashMap<>();
        Map<LineKey, Event> ordered = new TreeMap<>();
        for (Event event : events) {
            long client = event.client();
            int index = counted.merge(client, 1, Integer::sum) - 1;
            String name = rank.get(client);
            ordered.put(name != null ? new LineKey(tick, Step.APPLY, name, 0, index, 0)
                    : new LineKey(tick, Step.APPLY, "", client, index, 0), event);
        }
        return ordered;
    }

    /** Every grasp of the tick to the parcel of its fruit, in order; true when a fruit was taken. */
    private boolean grasp(List<Parcel.KeyedClaim> claims, List<KeyedLine> lines) {
        List<Parcel.KeyedClaim> ordered = new ArrayList<>(claims);
        ordered.removeIf(claim -> !roll.has(claim.claim().agent().name())); // it left during the tick
        ordered.sort((a, b) -> a.key().compareTo(b.key()));
        Map<String, LineKey> firstClaims = new HashMap<>();
        Map<ParcelId, List<Parcel.ClaimOf>> deciding = new TreeMap<>();
        for (Parcel.KeyedClaim keyed : ordered) {
            String fruit = keyed.claim().message().fruit();
            String agent = keyed.claim().agent().name();
            ParcelId at = fruitParcels.getOrDefault(fruit, roll.parcel(agent));
            if (!at.equals(roll.parcel(agent))) {
                counts.graspsAcrossBorders++;
            }
            firstClaims.putIfAbsent(fruit, keyed.key().in(Step.GRASP));
            Link owner = roll.owner(agent);
            deciding.computeIfAbsent(at, id -> new ArrayList<>())
                    .add(new Parcel.ClaimOf(keyed.claim(), owner.ref(), referee.label(owner)));
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
            referee.collected(fruit.agent(), fruit.fruit(), fruit.kind(), fruit.time());
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
        walked.owned().forEach(roll::update);
        if (!walked.left().isEmpty()) {
            counts.walkedTogether += walked.left().size();
            own.byAgent(tick, Step.WALK);
            Map<ParcelId, List<AgentHandover>> back = new TreeMap<>();
            for (AgentHandover agent : PartialSimulation.walkTogether(walked.left(), config, tick, next, own)) {
                back.computeIfAbsent(roll.parcel(agent.name()), id -> new ArrayList<>()).add(agent);
                roll.update(agent);
            }
            lines.addAll(own.take());
            parcels.walked(back);
        }
    }

    /** Agents that walked out of their parcel's square go to the parcel they walked into. */
    private void handOver() {
        Map<ParcelId, List<String>> leaving = new TreeMap<>();
        Map<ParcelId, List<OwnedAgent>> arriving = new TreeMap<>();
        for (AgentHandover agent : roll.states()) {
            ParcelId from = roll.parcel(agent.name());
            ParcelId into = grid.of(agent.position());
            if (!into.equals(from)) {
                leaving.computeIfAbsent(from, id -> new ArrayList<>()).add(agent.name());
                arriving.computeIfAbsent(into, id -> new ArrayList<>()).add(owned(agent));
                counts.handOvers++;
            }
        }
        if (!leaving.isEmpty()) {
            parcels.release(leaving);
            arriving.values().forEach(list -> list.forEach(agent -> roll.moveTo(agent.agent().name(),
                    grid.of(agent.agent().position()))));
            parcels.own(arriving);
        }
    }

    /**
     * The ghosts of every parcel that has agents of its own (an entry, perhaps empty, for each): the
     * agents of other parcels within its halo, as they are now. Parcels without agents of their own
     * need none.
     */
    Map<ParcelId, List<OwnedAgent>> ghosts() {
        Set<ParcelId> holding = roll.parcels();
        Map<ParcelId, List<OwnedAgent>> ghosts = new TreeMap<>();
        holding.forEach(id -> ghosts.put(id, new ArrayList<>()));
        for (AgentHandover agent : roll.states()) {
            ParcelId home = roll.parcel(agent.name());
            OwnedAgent ghost = owned(agent);
            for (ParcelId id : grid.seeing(agent.position().x(), agent.position().z())) {
                if (!id.equals(home) && holding.contains(id)) {
                    ghosts.get(id).add(ghost);
                }
            }
        }
        return ghosts;
    }

    /** Counts perceptions of an agent standing in another parcel than the perceiver's. */
    private void countSightings(List<KeyedLine> said) {
        for (KeyedLine line : said) {
            if (line.message() instanceof PerceptionMessage perception) {
                for (PerceivedAgent seen : perception.agents()) {
                    ParcelId there = roll.parcel(seen.name());
                    if (there != null && !there.equals(roll.parcel(perception.agent()))) {
                        counts.sightingsAcrossBorders++;
                    }
                }
            }
        }
    }

    private boolean lockstep() {
        return config.clock() == ClockMode.LOCKSTEP;
    }

    // ---- commands: on the game's thread ({@link #execute}) --------------------------------------

    /** Starts the game now; no effect once started. */
    public void start() {
        if (referee == null) {
            lobby.start();
        }
    }

    /** Pauses a running game or continues a paused one; returns the phase after. */
    public Phase togglePause() {
        return referee == null ? lobby.togglePause() : referee.togglePause();
    }

    /** Ends the game now with this reason; no effect once over. */
    public void end(String reason) {
        if (referee == null) {
            lobby.end(reason);
        } else {
            referee.end(reason);
        }
    }

    /**
     * Gives {@code to} a checkpoint when the game starts, after every tick in which fruit was
     * collected and when the game ends, so that nothing collected is lost to a crash. Call before the
     * game's thread starts.
     */
    public void checkpointWhenScored(Consumer<Checkpoint> to) {
        onScore = to;
    }

    /**
     * Takes a checkpoint at the end of the tick under way (at once while no ticks pass) and gives it
     * to {@code to} on the game's thread. Safe from any thread.
     */
    public void checkpointAtTickEnd(Consumer<Checkpoint> to) {
        execute(() -> atTickEnd.add(to));
    }

    /** Hands out the checkpoints due now: those asked for, and one for a score or the end. */
    private void saved(boolean scored) {
        boolean over = phase() == Phase.OVER;
        boolean forScore = onScore != null && (scored || over && !overSaved);
        if (!forScore && atTickEnd.isEmpty()) {
            return;
        }
        Checkpoint checkpoint = checkpoint();
        if (forScore) {
            onScore.accept(checkpoint);
            overSaved = over;
        }
        atTickEnd.forEach(to -> to.accept(checkpoint));
        atTickEnd.clear();
    }

    /** The whole game as it is now. */
    public Checkpoint checkpoint() {
        if (referee == null) {
            return lobby.checkpoint();
        }
        referee.refresh(roll.states());
        return referee.checkpoint();
    }

    // ---- state ---------------------------------------------------------------------------------

    /** The settings the game runs with. */
    public SimulationConfig config() {
        return config;
    }

    /** The current phase. */
    public Phase phase() {
        return referee != null ? referee.phase() : lobby.phase();
    }

    /** Whether the game went to its parcels: what they hold is part of the game from then on. */
    public boolean inParcels() {
        return referee != null;
    }

    /** The tick that runs now. */
    public long tick() {
        return referee != null ? tick : lobby.tick();
    }

    /** Simulated seconds since the start. */
    public double time() {
        return referee != null ? time : lobby.time();
    }

    /** Every agent's score, best first. */
    public List<Score> ranking() {
        return referee != null ? referee.ranking() : lobby.ranking();
    }

    /** Names of the agents in the game, by name. */
    public List<String> agentNames() {
        return referee != null ? referee.agents().stream().map(d -> d.agent().name()).toList() : lobby.agentNames();
    }

    /** Names of the agents of a restored game still waiting for their controllers. */
    public List<String> waitingAgents() {
        return referee != null ? referee.waitingAgents() : lobby.waitingAgents();
    }

    /** Fruit still in the world. */
    public int fruitLeft() {
        return world.fruitCount();
    }

    /** How much crossed parcels' borders so far. */
    public SplitCounts counts() {
        return counts.copy();
    }

    /** Where each agent is now, by name: the parcel that owns it. */
    public Map<String, ParcelId> parcelsOfAgents() {
        Map<String, ParcelId> where = new TreeMap<>();
        roll.states().forEach(agent -> where.put(agent.name(), roll.parcel(agent.name())));
        return where;
    }
}
