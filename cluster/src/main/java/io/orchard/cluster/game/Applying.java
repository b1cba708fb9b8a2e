package io.orchard.cluster.game;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.Merge;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.KeepAliveMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.PartialSimulation.Driven;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Referee;
import io.orchard.server.sim.SimulationConfig;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * What clients sent, applied in the single server's order once a split game has started: each
 * message about an agent by the parcel that owns the agent, everything else by the game's referee.
 * Parcels apply their messages side by side, as nothing an action reads is changed by another action
 * of the same tick; what changes who is in the world (an agent entering or leaving) is a border
 * between such rounds, applied where it comes in the order, so that the messages after it find the
 * world as the single server would.
 */
final class Applying {

    /** What a client did, queued for the game's thread. */
    record Event(Kind kind, ClientSession session, ClientMessage message, String reason, Runnable task) {

        /** What happened. */
        enum Kind { CONNECTED, RECEIVED, GONE, TASK }

        /** The number of the client it came from; -1 for the program's own work, which comes first. */
        long client() {
            return session == null ? -1 : session.id();
        }
    }

    /**
     * What a batch of events said, and the grasps asked for in it.
     *
     * @param lines  every line said, the parcels' and the referee's
     * @param claims the grasps, each with the place of its request
     */
    record Done(List<KeyedLine> lines, List<Parcel.KeyedClaim> claims) {}

    private final SplitGame game;
    private final Referee referee;
    private final Roll roll;
    private final Parcels parcels;
    private final ParcelGrid grid;
    private final SimulationConfig config;
    private final KeyedLines own;
    private final Merge merge;
    private final Map<Long, Link> links;
    private final Counters counts;
    // The batch being applied.
    private final Map<ParcelId, List<Parcel.Act>> acts = new TreeMap<>();
    private final List<KeyedLine> lines = new ArrayList<>();
    private final List<Parcel.KeyedClaim> claims = new ArrayList<>();
    private long tick;
    private double time;

    Applying(SplitGame game, Referee referee, Roll roll, Parcels parcels, ParcelGrid grid, SimulationConfig config,
             KeyedLines own, Merge merge, Map<Long, Link> links, Counters counts) {
        this.game = game;
        this.referee = referee;
        this.roll = roll;
        this.parcels = parcels;
        this.grid = grid;
        this.config = config;
        this.own = own;
        this.merge = merge;
        this.links = links;
        this.counts = counts;
    }

    /** Applies {@code events} in the order of their keys, at {@code tick} and simulated {@code time}. */
    Done apply(long tick, double time, Map<LineKey, Event> events) {
        this.tick = tick;
        this.time = time;
        events.forEach(this::take);
        round();
        lines.addAll(own.take());
        Done done = new Done(new ArrayList<>(lines), new ArrayList<>(claims));
        lines.clear();
        claims.clear();
        return done;
    }

    private void take(LineKey key, Event event) {
        switch (event.kind()) {
            case TASK -> {
                round();
                own.cause(key);
                event.task().run();
            }
            case CONNECTED -> {
                round();
                join(key, event.session());
            }
            case GONE -> {
                round();
                leave(key, event);
            }
            case RECEIVED -> received(key, event);
        }
    }

    /** A client connected: it catches up with the game, and hears what comes after. */
    private void join(LineKey key, ClientSession session) {
        Link link = new Link(session);
        link.keyedInto(own);
        links.put(session.id(), link);
        merge.connected(session);
        if (session.role() == Role.VIEWER) {
            referee.refresh(roll.states());
        }
        own.cause(key);
        for (ServerMessage message : referee.catchUp(link)) {
            own.caughtUp(link.ref(), message);
        }
        own.joined(link.ref());
    }

    /** A client's connection closed: its agents leave the world, kept for it. */
    private void leave(LineKey key, Event event) {
        Link link = links.remove(event.session().id());
        merge.leave(event.session());
        if (link == null) {
            return;
        }
        List<String> names = roll.namesOf(link.id());
        if (!names.isEmpty()) {
            referee.refresh(parcels.release(byParcel(names)));
        }
        own.cause(key);
        referee.leave(link, event.reason());
        gone(names);
    }

    private void received(LineKey key, Event event) {
        Link link = links.get(event.session().id());
        ClientMessage message = event.message();
        if (link == null || message instanceof KeepAliveMessage) {
            return; // it left, or it says only that it is there
        }
        if (message instanceof RegisterMessage register) {
            round();
            own.cause(key);
            enter(referee.register(link, register));
            return;
        }
        if (message instanceof AgentMessage about && link.role() == Role.AGENT && roll.owner(about.agent()) == link) {
            acts.computeIfAbsent(roll.parcel(about.agent()), id -> new ArrayList<>())
                    .add(new Parcel.Act(key, link.ref(), message, referee.phase()));
            if (message instanceof UnregisterMessage) {
                round();
            }
            return;
        }
        own.cause(key);
        referee.accepted(link, message);
        if (message instanceof AgentMessage about) {
            refuse(link, message.seq(), about.agent());
        } else if (message instanceof GameControlMessage control) {
            referee.control(link, control);
        } else if (message instanceof InstructionMessage instruction) {
            Link owner = roll.owner(instruction.agent());
            referee.send(owner != null ? owner : link, owner != null ? instruction : new ErrorMessage(
                    instruction.seq(), ErrorCode.UNKNOWN_AGENT, "no agent named '" + instruction.agent()
                    + "' in the world"));
        }
        // EndTurn matters to the tick; the rest is recorded only, as on one server.
    }

    /** Answers a message about an agent the client does not drive, as the single server's actions do. */
    private void refuse(Link link, long seq, String agent) {
        ErrorMessage error = link.role() != Role.AGENT
                ? new ErrorMessage(seq, ErrorCode.WRONG_ROLE, "a viewer cannot drive agents")
                : roll.owner(agent) == null ? new ErrorMessage(seq, ErrorCode.UNKNOWN_AGENT, "no agent named '"
                        + agent + "' in the world")
                : new ErrorMessage(seq, ErrorCode.NOT_YOUR_AGENT, "agent '" + agent
                        + "' belongs to another connection");
        referee.send(link, error);
    }

    /**
     * An agent entered the game: its parcel owns it, and the parcels around that have agents of
     * their own hold it as a ghost at once, for the messages still to come in this tick.
     */
    private void enter(Driven entered) {
        if (entered == null) {
            return;
        }
        AgentHandover agent = entered.agent().withoutModel();
        ParcelId home = grid.of(agent.position());
        boolean newHome = !roll.parcels().contains(home);
        roll.add(agent, (Link) entered.owner(), home);
        OwnedAgent owned = game.owned(agent);
        parcels.own(Map.of(home, List.of(owned)));
        Map<ParcelId, List<OwnedAgent>> seen = new TreeMap<>();
        Set<ParcelId> holding = roll.parcels();
        for (ParcelId id : grid.seeing(agent.position().x(), agent.position().z())) {
            if (!id.equals(home) && holding.contains(id)) {
                seen.put(id, List.of(owned));
            }
        }
        if (newHome) {
            List<OwnedAgent> around = game.ghosts().get(home);
            if (around != null && !around.isEmpty()) {
                seen.put(home, around);
            }
        }
        if (!seen.isEmpty()) {
            parcels.addGhosts(seen);
        }
    }

    /** Agents that left the game: out of the roll, and their ghosts forgotten. */
    private void gone(List<String> names) {
        Map<ParcelId, List<String>> forget = new TreeMap<>();
        Set<ParcelId> holding = roll.parcels();
        for (String name : names) {
            AgentHandover agent = roll.state(name);
            for (ParcelId id : grid.seeing(agent.position().x(), agent.position().z())) {
                if (!id.equals(roll.parcel(name)) && holding.contains(id)) {
                    forget.computeIfAbsent(id, i -> new ArrayList<>()).add(name);
                }
            }
        }
        names.forEach(roll::remove);
        if (!forget.isEmpty()) {
            parcels.forgetGhosts(forget);
        }
    }

    private Map<ParcelId, List<String>> byParcel(List<String> names) {
        Map<ParcelId, List<String>> by = new TreeMap<>();
        names.forEach(name -> by.computeIfAbsent(roll.parcel(name), id -> new ArrayList<>()).add(name));
        return by;
    }

    /** The messages about agents gathered so far, applied by their parcels side by side. */
    private void round() {
        if (acts.isEmpty()) {
            return;
        }
        Map<ParcelId, List<Parcel.Act>> now = new TreeMap<>(acts);
        acts.clear();
        Parcels.Applied applied = parcels.apply(tick, time, now, pathsBeyondHalos(now));
        lines.addAll(applied.lines());
        claims.addAll(applied.claims());
        applied.owned().forEach(roll::update); // facing and walking as the actions left them
        if (!applied.removed().isEmpty()) {
            applied.removed().forEach(referee::unregistered);
            gone(applied.removed());
        }
    }

    /**
     * The first contacts on the paths of the running game's moves that leave their parcel's halo,
     * from the parcels along them; every agent stands where it stood at the start of the tick until
     * it walks.
     */
    private Map<PathQuery, FirstContact> pathsBeyondHalos(Map<ParcelId, List<Parcel.Act>> applied) {
        Map<ParcelId, List<PathQuery>> asks = new TreeMap<>();
        List<PathQuery> beyond = new ArrayList<>();
        double maxRadius = config.bodyLimits().maxRadius();
        applied.forEach((home, some) -> {
            for (Parcel.Act act : some) {
                if (act.message() instanceof MoveMessage move && act.phase() == Phase.RUNNING) {
                    AgentHandover walker = roll.state(move.agent());
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
}
