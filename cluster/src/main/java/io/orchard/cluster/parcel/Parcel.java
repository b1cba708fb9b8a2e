package io.orchard.cluster.parcel;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.ProxySession;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.PartialSimulation;
import io.orchard.server.sim.PartialSimulation.Claim;
import io.orchard.server.sim.PartialSimulation.Driven;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * One parcel of the world: the single server's rules over its agents, its ghosts and its copy of the
 * fruit ({@link PartialSimulation}), every line it says kept with its place in the tick
 * ({@link KeyedLines}) for the merge. What it sends to a client waits in that line, so that the
 * client gets it in the single server's order.
 */
public final class Parcel {

    /**
     * A grasp with its place: where its request was applied.
     *
     * @param key   the place of the request
     * @param claim the grasp
     */
    public record KeyedClaim(LineKey key, Claim claim) {}

    private final ParcelId id;
    private final KeyedLines lines = new KeyedLines();
    private final PartialSimulation part;
    private final Map<Long, ProxySession> proxies = new HashMap<>();
    /** The places of this tick's grasp requests, in the order applied. */
    private final List<LineKey> requests = new ArrayList<>();

    /**
     * The parcel {@code id} of a game in {@code world} (a world of its own), telling {@code listener}
     * of fruit taken, asking {@code elsewhere} about walkers' paths that leave its halo.
     */
    public Parcel(ParcelId id, World world, SimulationConfig config, GameListener listener,
                  PartialSimulation.Elsewhere elsewhere) {
        this.id = id;
        this.part = new PartialSimulation(world, config, lines, listener, elsewhere);
    }

    /** Which parcel this is. */
    public ParcelId id() {
        return id;
    }

    private ProxySession proxy(ClientSession session) {
        return proxies.computeIfAbsent(session.id(), i -> new ProxySession(session, lines));
    }

    /** Takes an agent as its own. */
    public void own(Driven driven) {
        part.own(new Driven(driven.agent(), proxy(driven.owner()), driven.label()));
    }

    /** Holds a copy of another parcel's agent. */
    public void ghost(Driven driven) {
        part.ghost(new Driven(driven.agent(), proxy(driven.owner()), driven.label()));
    }

    /** Forgets every ghost. */
    public void forgetGhosts() {
        part.forgetGhosts();
    }

    /** Gives up an own agent; null when it has none of that name. */
    public AgentHandover release(String name) {
        return part.release(name);
    }

    /** The own agents as they are now. */
    public List<AgentHandover> owned() {
        return part.owned();
    }

    /** The own agent of that name, or null. */
    public AgentHandover state(String name) {
        return part.state(name);
    }

    /** The perceptions due at {@code tick}, at simulated {@code time}. */
    public void perceive(long tick, double time) {
        part.at(tick, time);
        lines.byAgent(tick, LineKey.Step.PERCEIVE);
        part.perceive(tick);
    }

    /** Applies a client's message about an own agent, at its place {@code key} of the tick. */
    public void act(LineKey key, long tick, double time, ClientSession session, ClientMessage message) {
        part.at(tick, time);
        lines.cause(key);
        part.act(proxy(session), message);
        if (message instanceof GraspRequestMessage) {
            requests.add(key);
        }
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

    /** A grasp of this parcel's fruit, by an agent driven by {@code owner}; give them in their order. */
    public void claim(Claim claim, ClientSession owner, String label) {
        part.claim(claim, proxy(owner), label);
    }

    /** Decides the grasps claimed, their lines in the places {@code firstClaims} gives each fruit. */
    public boolean resolveGrasps(long tick, double time, Function<String, LineKey> firstClaims) {
        part.at(tick, time);
        lines.byFruit(firstClaims);
        return part.resolveGrasps();
    }

    /** Walks its agents to {@code time}; returns those left to be walked with other parcels' agents. */
    public List<String> walk(long tick, double time) {
        part.at(tick, time);
        lines.byAgent(tick, LineKey.Step.WALK);
        return part.walk(time);
    }

    /** Puts an own agent where it was walked with other parcels' agents. */
    public void walked(AgentHandover agent) {
        part.walked(agent);
    }

    /** A fruit in its halo was taken. */
    public void fruitTaken(String fruit) {
        part.fruitTaken(fruit);
    }

    /** The first own agent a walker meets on a segment, or null. */
    public FirstContact firstAlong(String walker, Vec3 from, Vec3 to, double radius) {
        return part.firstAlong(walker, from, to, radius);
    }

    /** Takes the lines said since the last time. */
    public List<KeyedLine> takeLines() {
        return lines.take();
    }
}
