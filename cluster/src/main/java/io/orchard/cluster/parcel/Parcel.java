package io.orchard.cluster.parcel;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.ProxySession;
import io.orchard.cluster.order.SessionRef;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.value.FruitKind;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.PartialSimulation;
import io.orchard.server.sim.PartialSimulation.Claim;
import io.orchard.server.sim.PartialSimulation.Driven;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;

/**
 * One parcel of the world: the single server's rules over its agents, its ghosts and its copy of the
 * fruit ({@link PartialSimulation}), every line it says kept with its place in the tick
 * ({@link KeyedLines}) for the merge. What it sends to a client waits in that line, so that the
 * client gets it in the single server's order. It knows its clients by reference only
 * ({@link SessionRef}), so that it can live on any node.
 */
public final class Parcel {

    /**
     * A grasp with its place: where its request was applied.
     *
     * @param key   the place of the request
     * @param claim the grasp
     */
    public record KeyedClaim(LineKey key, Claim claim) {}

    /**
     * A fruit taken in a parcel.
     *
     * @param agent the agent that took it
     * @param fruit the fruit
     * @param kind  its kind
     * @param time  the simulated time
     */
    public record Taken(String agent, String fruit, FruitKind kind, double time) {}

    /**
     * All a parcel holds between two steps of a tick, to be taken up by the same parcel on another
     * node (Pekko hands a parcel over when its node leaves). A value, sent between nodes.
     *
     * @param own       its own agents, as they are now
     * @param ghosts    the other parcels' agents it holds
     * @param fruitGone the fruit of the world as made that is gone from its copy
     */
    public record State(List<OwnedAgent> own, List<OwnedAgent> ghosts, List<String> fruitGone) {

        /** Whether the parcel had agents of its own. */
        public boolean hasAgents() {
            return !own.isEmpty();
        }
    }

    private final ParcelId id;
    private final ParcelGrid grid;
    private final double maxRadius;
    private final KeyedLines lines = new KeyedLines();
    private final PartialSimulation part;
    private final Map<Long, ProxySession> proxies = new HashMap<>();
    /** Every agent it was given, own or ghost, as given: their clients and labels. */
    private final Map<String, OwnedAgent> known = new HashMap<>();
    private final World world;
    private final Set<String> fruitGone = new TreeSet<>();
    /** The places of this tick's grasp requests, in the order applied. */
    private final List<LineKey> requests = new ArrayList<>();
    private final List<Taken> taken = new ArrayList<>();
    /** Own agents that unregistered since last asked. */
    private final List<String> removed = new ArrayList<>();
    /** The first contacts on this tick's paths that leave the halo, as the parcels along them answered. */
    private Map<PathQuery, FirstContact> far = Map.of();

    /** The parcel {@code id} of {@code grid} in a game in {@code world} (a world of its own). */
    public Parcel(ParcelId id, ParcelGrid grid, World world, SimulationConfig config) {
        this.id = id;
        this.grid = grid;
        this.maxRadius = config.bodyLimits().maxRadius();
        GameListener listener = new GameListener() {
            @Override
            public void fruitEaten(String agent, String fruit, FruitKind kind, double time) {
                taken.add(new Taken(agent, fruit, kind, time));
            }

            @Override
            public void agentLeft(String agent, String reason) {
                removed.add(agent);
            }
        };
        this.world = world;
        this.part = new PartialSimulation(world, config, lines, listener, this::elsewhere);
    }

    /** Which parcel this is. */
    public ParcelId id() {
        return id;
    }

    /** Whether a walker's path leaves the halo, so that the parcels along it must be asked. */
    public static boolean leavesHalo(ParcelGrid grid, ParcelId parcel, PathQuery path, double maxRadius) {
        return !grid.holds(parcel, path, maxRadius);
    }

    private FirstContact elsewhere(String walker, io.orchard.protocol.value.Vec3 from,
                                   io.orchard.protocol.value.Vec3 to, double radius) {
        PathQuery path = new PathQuery(walker, from, to, radius);
        if (!leavesHalo(grid, id, path, maxRadius)) {
            return null;
        }
        if (!far.containsKey(path)) {
            throw new IllegalStateException("no answer from the parcels along " + path);
        }
        return far.get(path);
    }

    private ProxySession proxy(SessionRef session) {
        return proxies.computeIfAbsent(session.id(), i -> new ProxySession(session, lines));
    }

    private Driven driven(OwnedAgent agent) {
        known.put(agent.agent().name(), agent);
        return new Driven(agent.agent(), proxy(agent.owner()), agent.label());
    }

    /** Takes agents as its own. */
    public void own(List<OwnedAgent> agents) {
        agents.forEach(agent -> part.own(driven(agent)));
    }

    /** All it holds now. */
    public State state() {
        return new State(held(part.owned()), held(part.ghosts()), new ArrayList<>(fruitGone));
    }

    /** The agents as they are now, with the clients and labels they were given with. */
    private List<OwnedAgent> held(List<AgentHandover> agents) {
        List<OwnedAgent> held = new ArrayList<>();
        for (AgentHandover agent : agents) {
            OwnedAgent given = known.get(agent.name());
            held.add(new OwnedAgent(agent, given.owner(), given.label()));
        }
        return held;
    }

    /** Takes up what the same parcel held on another node. */
    public void restore(State state) {
        fruitTaken(state.fruitGone());
        own(state.own());
        addGhosts(state.ghosts());
    }

    /** Keeps only this fruit of the world as made: the rest was taken before it came to be. */
    public void keepOnly(Set<String> fruitLeft) {
        List<String> gone = new ArrayList<>();
        world.fruit().forEach(fruit -> {
            if (!fruitLeft.contains(fruit.id())) {
                gone.add(fruit.id());
            }
        });
        fruitTaken(gone);
    }

    /** Holds these copies of other parcels' agents, and no other. */
    public void ghosts(List<OwnedAgent> ghosts) {
        part.forgetGhosts();
        ghosts.forEach(ghost -> part.ghost(driven(ghost)));
    }

    /** Gives up own agents; returns them as they are now (none for a name it does not own). */
    public List<AgentHandover> release(List<String> names) {
        List<AgentHandover> released = new ArrayList<>();
        for (String name : names) {
            AgentHandover agent = part.release(name);
            if (agent != null) {
                released.add(agent);
            }
        }
        return released;
    }

    /** Holds these copies of other parcels' agents too, in place of any it held of them. */
    public void addGhosts(List<OwnedAgent> ghosts) {
        ghosts.forEach(ghost -> part.ghost(driven(ghost)));
    }

    /** Forgets the ghosts of agents that left the game. */
    public void forgetGhosts(List<String> names) {
        names.forEach(part::forgetGhost);
    }

    /** The own agents that unregistered since last asked; forgets them. */
    public List<String> takeRemoved() {
        List<String> gone = new ArrayList<>(removed);
        removed.clear();
        return gone;
    }

    /** The own agents as they are now. */
    public List<AgentHandover> owned() {
        return part.owned();
    }

    /** The perceptions due at {@code tick}, at simulated {@code time}; returns their lines. */
    public List<KeyedLine> perceive(long tick, double time) {
        part.at(tick, time);
        lines.byAgent(tick, LineKey.Step.PERCEIVE);
        part.perceive(tick);
        return lines.take();
    }

    /** The first own agent each walker meets on its path, or null for a path that meets none. */
    public List<FirstContact> firstAlong(List<PathQuery> paths) {
        List<FirstContact> first = new ArrayList<>();
        for (PathQuery path : paths) {
            first.add(part.firstAlong(path.walker(), path.from(), path.to(), path.radius()));
        }
        return first;
    }

    /**
     * Applies clients' messages about own agents, each at its place of the tick, in that order;
     * {@code answers} are the first contacts on the paths that leave the halo.
     */
    public List<KeyedLine> apply(long tick, double time, List<Act> acts, Map<PathQuery, FirstContact> answers) {
        part.at(tick, time);
        far = answers;
        for (Act act : acts) {
            lines.cause(act.key());
            part.act(proxy(act.session()), act.message(), act.phase());
            if (act.message() instanceof GraspRequestMessage) {
                requests.add(act.key());
            }
        }
        far = Map.of();
        return lines.take();
    }

    /** The grasps its agents asked for in this tick, each with the place of its request. */
    public List<KeyedClaim> takeClaims() {
        List<Claim> claims = part.takeClaims();
        if (claims.size() != requests.size()) {
            throw new IllegalStateException(claims.size() + " grasps taken for " + requests.size() + " requests");
        }
        List<KeyedClaim> keyed = new ArrayList<>();
        for (int i = 0; i < claims.size(); i++) {
            keyed.add(new KeyedClaim(requests.get(i), claims.get(i)));
        }
        requests.clear();
        return keyed;
    }

    /**
     * Decides the grasps of this parcel's fruit, given in the order of their requests, their lines in
     * the places {@code firstClaims} gives each fruit; returns the lines, and adds the fruit taken.
     */
    public List<KeyedLine> grasp(long tick, double time, List<ClaimOf> claims, Function<String, LineKey> firstClaims,
                                 List<Taken> took) {
        claims.forEach(c -> {
            known.put(c.claim().agent().name(), new OwnedAgent(c.claim().agent(), c.owner(), c.label()));
            part.claim(c.claim(), proxy(c.owner()), c.label());
        });
        part.at(tick, time);
        lines.byFruit(firstClaims);
        taken.clear();
        part.resolveGrasps();
        taken.forEach(fruit -> fruitGone.add(fruit.fruit()));
        took.addAll(taken);
        return lines.take();
    }

    /** Fruit in its halo was taken. */
    public void fruitTaken(List<String> fruit) {
        fruitGone.addAll(fruit);
        fruit.forEach(part::fruitTaken);
    }

    /** Walks its agents to {@code time}; returns the lines, and adds those left to be walked with others. */
    public List<KeyedLine> walk(long tick, double time, List<AgentHandover> left) {
        part.at(tick, time);
        lines.byAgent(tick, LineKey.Step.WALK);
        for (String name : part.walk(time)) {
            left.add(part.state(name));
        }
        return lines.take();
    }

    /** Puts own agents where they were walked with other parcels' agents. */
    public void walked(List<AgentHandover> agents) {
        agents.forEach(part::walked);
    }

    /**
     * A client's message about an own agent, at its place of the tick. A value, sent between nodes.
     *
     * @param key     its place
     * @param session the client that sent it
     * @param message the message
     * @param phase   the game's phase when it is applied
     */
    public record Act(LineKey key, SessionRef session, ClientMessage message, Phase phase) {}

    /**
     * A grasp of a parcel's fruit, with the client of the grasping agent. A value, sent between nodes.
     *
     * @param claim the grasp
     * @param owner the client of the grasping agent
     * @param label that client's label
     */
    public record ClaimOf(Claim claim, SessionRef owner, String label) {}
}
