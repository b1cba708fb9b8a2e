package io.orchard.server.sim;

import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Recorder.Audience;

/**
 * Moves walking agents along their paths and keeps them from walking into each other. Agents are
 * found through a uniform grid rebuilt each tick, so the cost grows with the number of agents, not
 * with its square.
 */
final class Walking {

    /** Where a move meets another agent: the walker stops at {@code stop}, touching {@code other}. */
    record Contact(Agent other, Vec3 stop) {}

    /** Grid cell size: twice the largest body radius, so touching agents are in neighbouring cells. */
    private static final double CELL = 4.0;

    private final Simulation sim;

    Walking(Simulation sim) {
        this.sim = sim;
    }

    /** The first agent the segment from {@code from} to {@code to} runs into, or null if none. */
    Contact contact(Agent mover, Vec3 from, Vec3 to) {
        double dx = to.x() - from.x();
        double dz = to.z() - from.z();
        double length = Math.hypot(dx, dz);
        Agent first = null;
        double firstT = Double.MAX_VALUE;
        for (Agent other : sim.agents.values()) {
            if (other == mover) {
                continue;
            }
            double reach = mover.body.radius() + other.body.radius();
            double t = entry(from, dx, dz, length, other.position, reach);
            if (t < firstT) {
                firstT = t;
                first = other;
            }
        }
        if (first == null) {
            return null;
        }
        double travel = Math.max(0, firstT - 1e-3);
        return new Contact(first, new Vec3(from.x() + dx / length * travel, 0, from.z() + dz / length * travel));
    }

    /**
     * The distance along the segment at which a walker comes within {@code reach} of {@code centre},
     * or MAX_VALUE if it never does. A walker already that close counts only if it walks closer.
     */
    private static double entry(Vec3 from, double dx, double dz, double length, Vec3 centre, double reach) {
        if (length == 0) {
            return Double.MAX_VALUE;
        }
        double ux = dx / length;
        double uz = dz / length;
        double cx = centre.x() - from.x();
        double cz = centre.z() - from.z();
        double along = cx * ux + cz * uz;
        double startGap = Math.hypot(cx, cz);
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
        for (Agent other : sim.agents.values()) {
            if (other != except && other.position.groundDistance(point) < radius + other.body.radius()) {
                return false;
            }
        }
        return true;
    }

    /** Moves every walking agent to where it is at {@code time}; one that would touch another stops. */
    void advance(double time) {
        AgentGrid grid = new AgentGrid(sim.agents.values(), CELL);
        for (Agent agent : sim.agents.values()) {
            Motion motion = agent.motion;
            if (motion == null) {
                continue;
            }
            Vec3 next = motion.positionAt(time);
            if (touchesAnother(grid, agent, next)) {
                agent.motion = null;
                sim.broadcast(new AgentMovedMessage(sim.tick(), agent.name, agent.position, agent.position, time, 0),
                        Audience.VIEWERS);
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
