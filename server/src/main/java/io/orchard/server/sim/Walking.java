package io.orchard.server.sim;

import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Recorder.Audience;
import java.util.Map;

/**
 * Moves walking agents along their paths and keeps them from walking into each other. Agents are
 * found through a uniform grid, built when agents join or leave and kept true as they walk, so the
 * cost grows with the number of agents, not with its square.
 */
final class Walking {

    /** Where a move meets another agent: the walker stops at {@code stop}, touching {@code other}. */
    record Contact(Agent other, Vec3 stop) {}

    /**
     * The first agent a walker's segment meets among agents this walking does not hold, for a part
     * of a world whose agents may walk beyond it.
     */
    interface Beyond {
        /** The first agent held elsewhere that the segment meets, or null when none does or all are held here. */
        FirstContact first(Agent mover, Vec3 from, Vec3 to);
    }

    /** Grid cell size: twice the largest body radius, so touching agents are in neighbouring cells. */
    private static final double CELL = 4.0;

    /** The agents in the world, by name. */
    private final Map<String, Agent> agents;
    /** The largest radius a body may have: how far from a walker's path another agent may stand and touch it. */
    private final double maxRadius;
    private final Outbox outbox;
    private AgentGrid grid;
    /** Who answers for the agents beyond those held here; null when every agent is held here. */
    Beyond beyond;

    Walking(Map<String, Agent> agents, double maxRadius, Outbox outbox) {
        this.agents = agents;
        this.maxRadius = maxRadius;
        this.outbox = outbox;
    }

    /** The first agent the segment from {@code from} to {@code to} runs into, or null if none. */
    Contact contact(Agent mover, Vec3 from, Vec3 to) {
        double dx = to.x() - from.x();
        double dz = to.z() - from.z();
        double length = Math.sqrt(dx * dx + dz * dz);
        if (length == 0) {
            return null;
        }
        // Only agents whose centre lies within reach of the segment's box can be met.
        double margin = mover.body.radius() + maxRadius;
        double minX = Math.min(from.x(), to.x()) - margin;
        double minZ = Math.min(from.z(), to.z()) - margin;
        double maxX = Math.max(from.x(), to.x()) + margin;
        double maxZ = Math.max(from.z(), to.z()) + margin;
        Nearest nearest = new Nearest(mover, from, dx, dz, length);
        AgentGrid grid = grid();
        if (grid.cellsIn(minX, minZ, maxX, maxZ) < agents.size()) {
            grid.forEachInBox(minX, minZ, maxX, maxZ, nearest);
        } else {
            agents.values().forEach(nearest);
        }
        if (beyond != null) {
            FirstContact far = beyond.first(mover, from, to);
            if (far != null && nearest.closer(far.distance(), far.agent())) {
                nearest.firstT = far.distance();
                nearest.first = new Agent(far.agent(), mover.owner, mover.body, null, to, 0, "elsewhere");
            }
        }
        if (nearest.first == null) {
            return null;
        }
        double travel = Math.max(0, nearest.firstT - 1e-3);
        return new Contact(nearest.first, new Vec3(from.x() + dx / length * travel, 0, from.z() + dz / length * travel));
    }

    /**
     * The agent a walker meets first along its segment; ties go to the earlier name, as agents are
     * applied in the order of their names, whichever joined first.
     */
    private static final class Nearest implements java.util.function.Consumer<Agent> {
        private final Agent mover;
        private final Vec3 from;
        private final double dx;
        private final double dz;
        private final double length;
        Agent first;
        double firstT = Double.MAX_VALUE;

        Nearest(Agent mover, Vec3 from, double dx, double dz, double length) {
            this.mover = mover;
            this.from = from;
            this.dx = dx;
            this.dz = dz;
            this.length = length;
        }

        @Override
        public void accept(Agent other) {
            if (other == mover) {
                return;
            }
            double t = entry(from, dx, dz, length, other.position, mover.body.radius() + other.body.radius());
            if (closer(t, other.name)) {
                firstT = t;
                first = other;
            }
        }

        /** Whether meeting the agent of that name at {@code t} along the segment comes before the first so far. */
        boolean closer(double t, String name) {
            return t < firstT || (t == firstT && t != Double.MAX_VALUE && name.compareTo(first.name) < 0);
        }
    }

    /** The agents by where they stand, built when first asked for after the agents changed. */
    private AgentGrid grid() {
        if (grid == null) {
            grid = new AgentGrid(agents.values(), CELL);
        }
        return grid;
    }

    /** Agents joined, left or moved: the grid must be built again before it is used. */
    void agentsChanged() {
        grid = null;
    }

    /**
     * The distance along the segment at which a walker comes within {@code reach} of {@code centre},
     * or MAX_VALUE if it never does. A walker already that close counts only if it walks closer.
     */
    static double entry(Vec3 from, double dx, double dz, double length, Vec3 centre, double reach) {
        double ux = dx / length;
        double uz = dz / length;
        double cx = centre.x() - from.x();
        double cz = centre.z() - from.z();
        double along = cx * ux + cz * uz;
        double startGap = Math.sqrt(cx * cx + cz * cz);
        if (startGap < reach) {
            return along > 0 ? 0 : Double.MAX_VALUE;
        }
        double across2 = cx * cx + cz * cz - along * along;
        double reach2 = reach * reach;
        if (along < 0 || across2 >= reach2) {
            return Double.MAX_VALUE;
        }
        double t = along - Math.sqrt(reach2 - across2);
        return t <= length ? t : Double.MAX_VALUE;
    }

    /** Whether a body of {@code radius} at {@code point} would touch no agent but {@code except}. */
    boolean clearOfAgents(Vec3 point, double radius, Agent except) {
        for (Agent other : agents.values()) {
            if (other != except && other.position.groundDistance(point) < radius + other.body.radius()) {
                return false;
            }
        }
        return true;
    }

    /** Moves every walking agent to where it is at {@code time}; one that would touch another stops. */
    void advance(double time) {
        AgentGrid grid = grid(); // moved along with the agents below, so it stays true
        for (Agent agent : agents.values()) {
            Motion motion = agent.motion;
            if (motion == null) {
                continue;
            }
            Vec3 next = motion.positionAt(time);
            if (touchesAnother(grid, agent, next)) {
                agent.motion = null;
                outbox.broadcast(new AgentMovedMessage(outbox.tick(), agent.name, agent.position, agent.position,
                        time, 0), Audience.VIEWERS);
                continue;
            }
            grid.move(agent, next);
            agent.position = next;
            if (motion.finishedAt(time)) {
                agent.motion = null;
            }
        }
    }

    private static boolean touchesAnother(AgentGrid grid, Agent agent, Vec3 at) {
        boolean[] touches = {false};
        grid.forEachWithin(at, CELL, other -> {
            if (other != agent && !touches[0]) {
                double reach = agent.body.radius() + other.body.radius();
                double now = other.position.groundDistance(at);
                // Agents already overlapping may still walk apart.
                touches[0] = now < reach - 1e-6 && now < other.position.groundDistance(agent.position) - 1e-9;
            }
        });
        return touches[0];
    }
}
