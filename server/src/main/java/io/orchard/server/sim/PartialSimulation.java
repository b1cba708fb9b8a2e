package io.orchard.server.sim;

import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * The simulation of a part of a world, for a program that runs one world in parts on several
 * threads or machines (Orchard's cluster). A part holds the agents it <em>owns</em> and
 * <em>ghosts</em>: copies of agents owned by other parts, near enough to be seen or touched by its
 * own. It applies its own agents' actions, decides the grasps of the fruit it is given, computes its
 * own agents' perceptions and walks them, with the single server's rules ({@code Actions},
 * {@code Grasps}, {@code Walking}, {@code Perceptions}), so that the parts together play the game the
 * single server plays.
 *
 * <p>What it says goes to the {@link Recorder} it is given, every message sent to one client, to an
 * audience or received, with the tick and time it is said at ({@link #at}); messages to one client
 * also go to that client's {@link ClientSession}. It joins no session: broadcasts reach clients
 * through the recorder, whose caller knows who is connected where. The caller puts the parts'
 * lines in the single server's order.
 *
 * <p>Not thread-safe: one thread at a time, as a {@link Simulation}.
 */
public final class PartialSimulation {

    /**
     * A grasp asked for in this tick, with the grasping agent as it stands and faces once the
     * tick's actions are applied.
     *
     * @param agent   the grasping agent
     * @param message the request
     */
    public record Claim(AgentHandover agent, GraspRequestMessage message) {}

    /**
     * An agent with the session that drives it and the label the record names that session by.
     *
     * @param agent the agent
     * @param owner its controller's session
     * @param label the name of the session's first agent, as recordings name a client
     */
    public record Driven(AgentHandover agent, ClientSession owner, String label) {}

    /** Answers for the agents a part does not hold, on the paths of its walkers. */
    @FunctionalInterface
    public interface Elsewhere {
        /**
         * The first agent owned by another part that a walker of this radius meets on the segment;
         * null when none does. Ties go to the earlier name, as on one server.
         */
        FirstContact first(String walker, Vec3 from, Vec3 to, double radius);
    }

    /** Cell size of the grid that finds agents near a perceiving agent, as the single server's. */
    private static final double PERCEPTION_CELL = 25;

    private final World world;
    private final SimulationConfig config;
    private final Outbox outbox;
    /** Own agents and ghosts, by name: every pass goes in the order of the names. */
    private final Map<String, Agent> agents = new TreeMap<>();
    private final Set<String> ghosts = new HashSet<>();
    private final Walking walking;
    private final Grasps grasps;
    private final Actions actions;
    private final Perceptions perceptions;

    /**
     * A part of a game in {@code world} (a world of its own, {@link World#withOwnFruit()}), saying
     * what it does to {@code recorder}, telling {@code listener} of fruit collected and agents that
     * left, and asking {@code elsewhere} about walkers' paths that leave what it holds (null: it
     * holds every agent a path could meet).
     */
    public PartialSimulation(World world, SimulationConfig config, Recorder recorder, GameListener listener,
                             Elsewhere elsewhere) {
        this.world = world;
        this.config = config;
        this.outbox = new Outbox(recorder);
        outbox.release(); // a part runs a game that has started: nothing is held back for the start
        Scoreboard scores = new Scoreboard();
        List<GameListener> listeners = List.of(listener);
        this.walking = new Walking(agents, config.bodyLimits().maxRadius(), outbox);
        if (elsewhere != null) {
            walking.beyond = (mover, from, to) -> elsewhere.first(mover.name, from, to, mover.body.radius());
        }
        this.grasps = new Grasps(world, agents, scores, outbox, listeners);
        Game game = new Game(world, config, 0, scores, outbox, listeners, () -> { });
        Registrations registrations = new Registrations(world, config, 0, (name, radius) -> null, agents, scores,
                walking, game, outbox, listeners);
        this.actions = new Actions(world, agents, walking, grasps, registrations, outbox);
        this.perceptions = new Perceptions(world);
    }

    // ---- the agents ------------------------------------------------------------------------------

    /** Takes an agent as its own: one that walked in, or entered the world here. */
    public void own(Driven driven) {
        put(driven);
        ghosts.remove(driven.agent().name());
    }

    /** Holds a copy of another part's agent, as it stands now; replaces the copy held before. */
    public void ghost(Driven driven) {
        put(driven);
        ghosts.add(driven.agent().name());
    }

    private void put(Driven driven) {
        agents.put(driven.agent().name(), Agent.of(driven.agent(), driven.owner()));
        outbox.labelled(driven.owner(), driven.label());
        walking.agentsChanged();
    }

    /** Forgets the ghost of that name, if it holds one: the agent left the game. */
    public void forgetGhost(String name) {
        if (ghosts.remove(name)) {
            agents.remove(name);
            walking.agentsChanged();
        }
    }

    /** Forgets every ghost: fresh copies follow. */
    public void forgetGhosts() {
        ghosts.forEach(agents::remove);
        ghosts.clear();
        walking.agentsChanged();
    }

    /** Gives up an own agent (to the part it walked into); null when it owns none of that name. */
    public AgentHandover release(String name) {
        Agent agent = agents.get(name);
        if (agent == null || ghosts.contains(name)) {
            return null;
        }
        agents.remove(name);
        walking.agentsChanged();
        return agent.handover();
    }

    /** Whether the agent of that name is this part's own. */
    public boolean owns(String name) {
        return agents.containsKey(name) && !ghosts.contains(name);
    }

    /** The own agents as they are now, by name. */
    public List<AgentHandover> owned() {
        List<AgentHandover> own = new ArrayList<>();
        for (Agent agent : agents.values()) {
            if (!ghosts.contains(agent.name)) {
                own.add(agent.handover());
            }
        }
        return own;
    }

    /** The ghosts held, as they are now, by name. */
    public List<AgentHandover> ghosts() {
        List<AgentHandover> held = new ArrayList<>();
        for (Agent agent : agents.values()) {
            if (ghosts.contains(agent.name)) {
                held.add(agent.handover());
            }
        }
        return held;
    }

    /** The own agent of that name as it is now, or null. */
    public AgentHandover state(String name) {
        return owns(name) ? agents.get(name).handover() : null;
    }

    /** Puts an own agent where another part walked it (with its walk, or none when it stopped). */
    public void walked(AgentHandover agent) {
        Agent own = agents.get(agent.name());
        if (own != null && !ghosts.contains(agent.name())) {
            own.position = agent.position();
            own.motion = agent.walk() == null ? null : agent.walk().motion();
            walking.agentsChanged();
        }
    }

    /** A fruit was taken by another part. */
    public void fruitTaken(String fruit) {
        world.removeFruit(fruit);
    }

    // ---- the tick -------------------------------------------------------------------------------

    /** Sets the clock that stamps what is said from now on. */
    public void at(long tick, double time) {
        outbox.at(tick, time);
    }

    /**
     * The perceptions due at {@code tick} of the own agents, in the order of their names, from what
     * stands in the world now (own agents, ghosts and fruit). Ghosts never perceive here.
     */
    public void perceive(long tick) {
        CrowdGrid.Query crowd = null;
        for (Agent agent : agents.values()) {
            if (ghosts.contains(agent.name) || !agent.perceivesIn(tick)) {
                continue;
            }
            crowd = crowd != null ? crowd : CrowdGrid.of(agents.values(), PERCEPTION_CELL);
            outbox.send(agent.owner, perceptions.of(agent, crowd, tick));
            agent.perceptionRequested = false;
            if (agent.perceptionEvery > 0) {
                agent.nextPerceptionTick = tick + agent.perceptionEvery;
            }
        }
    }

    /**
     * Applies a message that {@code session} sent about one of this part's own agents in a game at
     * {@code phase} (once it has started), recording it first, as the single server applies it.
     *
     * @throws IllegalArgumentException when the message is not about an agent
     */
    public void act(ClientSession session, ClientMessage message, Phase phase) {
        if (!(message instanceof AgentMessage action)) {
            throw new IllegalArgumentException("a part applies messages about agents, not "
                    + message.getClass().getSimpleName());
        }
        outbox.from(session);
        outbox.accepted(session, message);
        actions.act(session, message.seq(), action, phase);
        outbox.from(null);
    }

    /**
     * The grasps this part's agents asked for in this tick, in the order they were asked for, each
     * with its agent as it stands and faces now; forgets them here. They go to the parts that own
     * the fruit ({@link #claim}), this one included.
     */
    public List<Claim> takeClaims() {
        List<Claim> claims = new ArrayList<>();
        for (Grasps.Request request : grasps.take()) {
            claims.add(new Claim(request.agent().handover(), request.message()));
        }
        return claims;
    }

    /**
     * A grasp of this part's fruit; claims are given in the order the single server applied their
     * requests. A grasping agent this part does not own is held as a ghost facing where it faces.
     */
    public void claim(Claim claim, ClientSession owner, String label) {
        Agent agent = agents.get(claim.agent().name());
        if (agent == null || ghosts.contains(claim.agent().name())) {
            ghost(new Driven(claim.agent(), owner, label));
            agent = agents.get(claim.agent().name());
        }
        grasps.request(agent, claim.message(), true);
    }

    /** Decides the claims given; true when a fruit was taken. Tells the listener whose. */
    public boolean resolveGrasps() {
        return grasps.resolve(outbox.tick(), outbox.time());
    }

    /**
     * The first of this part's own agents that a walker of {@code radius} meets on the segment, by
     * the single server's rule; null when none does.
     */
    public FirstContact firstAlong(String walker, Vec3 from, Vec3 to, double radius) {
        double dx = to.x() - from.x();
        double dz = to.z() - from.z();
        double length = Math.sqrt(dx * dx + dz * dz);
        if (length == 0) {
            return null;
        }
        FirstContact first = null;
        for (Agent other : agents.values()) {
            if (ghosts.contains(other.name) || other.name.equals(walker)) {
                continue;
            }
            double t = Walking.entry(from, dx, dz, length, other.position, radius + other.body.radius());
            FirstContact contact = new FirstContact(t, other.name);
            if (t != Double.MAX_VALUE && contact.before(first)) {
                first = contact;
            }
        }
        return first;
    }

    /**
     * Walks the agents one tick, to simulated {@code time}, as the single server does: one after the
     * other in the order of their names, each stopping where it would touch one walked before it.
     * Only agents that could touch each other depend on each other's order ({@link Touching}). A set
     * of such agents all of which are this part's own is walked here; a set with a ghost in it
     * reaches into other parts, whose own members of it are left to be walked together with the
     * rest of the set ({@link #walkTogether}). The ghosts must stand and walk as their owners have
     * them after the tick's actions, and reach farther than agents can touch across a tick.
     *
     * @return the own agents left unwalked, by name
     */
    public List<String> walk(double time) {
        double step = config.bodyLimits().maxSpeed() * config.tickSeconds();
        List<List<Agent>> sets = Touching.sets(new ArrayList<>(agents.values()), time,
                config.bodyLimits().maxRadius(), step);
        List<String> left = new ArrayList<>();
        for (List<Agent> set : sets) {
            if (set.stream().noneMatch(a -> ghosts.contains(a.name))) {
                Map<String, Agent> together = new TreeMap<>();
                set.forEach(a -> together.put(a.name, a));
                new Walking(together, config.bodyLimits().maxRadius(), outbox).advance(time);
            } else {
                set.stream().filter(a -> !ghosts.contains(a.name)).forEach(a -> left.add(a.name));
            }
        }
        walking.agentsChanged();
        return left;
    }

    /**
     * How far from a part's own agents its ghosts must reach for {@link #walk} to be the single
     * server's: twice the widest body plus twice the longest step of a tick.
     */
    public static double touchingReach(SimulationConfig config) {
        return 2 * config.bodyLimits().maxRadius() + 2 * config.bodyLimits().maxSpeed() * config.tickSeconds();
    }

    /**
     * Walks these agents one tick together, as the single server walks them, recording to
     * {@code recorder} at {@code tick}; for the sets of agents no one part holds whole.
     *
     * @return the agents where they stand afterwards, with their walks (none once stopped or done)
     */
    public static List<AgentHandover> walkTogether(Collection<AgentHandover> walkers, SimulationConfig config,
                                                   long tick, double time, Recorder recorder) {
        Outbox outbox = new Outbox(recorder);
        outbox.release();
        outbox.at(tick, time);
        Map<String, Agent> together = new TreeMap<>();
        ClientSession nobody = new Nobody();
        walkers.forEach(w -> together.put(w.name(), Agent.of(w, nobody)));
        new Walking(together, config.bodyLimits().maxRadius(), outbox).advance(time);
        List<AgentHandover> after = new ArrayList<>();
        for (AgentHandover before : walkers) {
            Agent agent = together.get(before.name());
            after.add(before.at(agent.position, AgentHandover.Walk.of(agent.motion)));
        }
        return after;
    }

    /** Writes out what was said since the last flush. */
    public void flush() {
        outbox.flush();
    }

    /** A session for agents walked where their controllers are not: nothing is sent to it. */
    private static final class Nobody implements ClientSession {
        @Override
        public long id() {
            return -1;
        }

        @Override
        public Role role() {
            return Role.AGENT;
        }

        @Override
        public void send(ServerMessage message) {}

        @Override
        public void send(EncodedLine line) {}

        @Override
        public void flush() {}

        @Override
        public void close(ErrorMessage last) {}

        @Override
        public boolean isOpen() {
            return false;
        }
    }
}
