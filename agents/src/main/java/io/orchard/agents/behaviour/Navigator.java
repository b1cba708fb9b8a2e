package io.orchard.agents.behaviour;

import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.Circle;
import io.orchard.agents.map.Obstruction;
import io.orchard.agents.map.SeenAgent;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Goes to a point: plans a path over the remembered map, walks it a stretch at a time, and plans
 * again when the map changes under the path. It reacts to what the plan did not know: a rejected
 * move (the memory has already learnt from its reason, "path crosses tree T17") makes it plan
 * again around what it learnt; another agent in the way, or a move the server cut short because an
 * agent blocked it, makes it plan around the agents it sees for a while.
 *
 * <pre>{@code
 * Navigator navigator = new Navigator(memory, motor, new PathPlanner(memory));
 * // once per tick:
 * if (navigator.goTo(new Point2(10, -20), 0.5) == Status.DONE) { ... }
 * }</pre>
 */
public final class Navigator {

    /** The longest single move it sends: farther points are walked to a stretch at a time. */
    public static final double MAX_STEP = 8;

    private static final double AGENT_LOOKAHEAD = 6;
    private static final double AGENT_ROOM = 0.3;
    private static final int MAX_REJECTIONS = 3;
    private static final double STUCK_SECONDS = 3;

    private final WorldMemory memory;
    private final Motor motor;
    private final PathPlanner planner;
    private double faceBeyond = 0;
    private Point2 target;
    private List<Point2> route;
    private int index;
    private long routeVersion = -1;
    private MoveStatus handled;
    private int rejections;
    private int stalls;
    private double avoidAgentsUntil = -1;
    private Point2 progressAt;
    private double progressTime;

    /** A navigator for the agent that {@code motor} drives and {@code memory} remembers for. */
    public Navigator(WorldMemory memory, Motor motor, PathPlanner planner) {
        this.memory = memory;
        this.motor = motor;
        this.planner = planner;
    }

    /**
     * How far (radians) the way may lie off the agent's heading before the agent turns to face it:
     * 0, the default, faces the way of every move; an agent that walks in any direction can keep
     * its heading for ways up to, say, 100 degrees to either side, and still turn rather than walk
     * backwards into what it cannot see.
     */
    public Navigator faceBeyond(double radians) {
        this.faceBeyond = Math.max(0, radians);
        return this;
    }

    /** The planner it plans with. */
    public PathPlanner planner() {
        return planner;
    }

    /** The point it is going to; null when idle. */
    public Point2 target() {
        return target;
    }

    /** The points still to walk through; empty when idle or not yet planned. */
    public List<Point2> route() {
        return route == null ? List.of() : List.copyOf(route.subList(index, route.size()));
    }

    /**
     * Stops where the agent stands and turns it to face {@code point}, to look at it: the next
     * perception shows what lies that way. Forgets the current target.
     */
    public void face(Point2 point) {
        reset();
        if (motor.walking()) {
            motor.halt();
        }
        double facing = Bearings.headingTowards(motor.position(), point);
        if (Math.abs(Bearings.normalise(facing - motor.heading())) > 0.02) {
            motor.turnTo(facing);
        }
    }

    /** Forgets the current target (without stopping a move under way). */
    public void reset() {
        target = null;
        route = null;
        rejections = 0;
        stalls = 0;
    }

    /**
     * One tick towards {@code goal}: DONE once the agent stands within {@code tolerance} of it,
     * FAILED when there is no known way there (or the way keeps being refused), else RUNNING.
     */
    public Status goTo(Point2 goal, double tolerance) {
        Point2 here = motor.position();
        if (target == null || target.distance(goal) > 0.25) {
            reset();
            target = goal;
            progressAt = here;
            progressTime = motor.time();
        }
        if (here.distance(goal) <= tolerance) {
            MoveStatus last = motor.lastMove();
            if (motor.walking() && last != null && last.to().distance(goal) > tolerance) {
                motor.halt();
            }
            return Status.DONE;
        }
        if (!learnFromLastMove()) {
            return Status.FAILED;
        }
        if (stalled(here)) {
            if (++stalls >= 3) {
                return Status.FAILED;
            }
            route = null;
            avoidAgentsUntil = motor.time() + STUCK_SECONDS;
        }
        List<Circle> others = others(here);
        if (route == null || (memory.terrainVersion() != routeVersion && !stillClear(here, others))) {
            if (!replan(here, goal, others)) {
                return Status.FAILED;
            }
        }
        while (index < route.size() - 1 && (here.distance(route.get(index)) < 0.3
                || planner.clear(here, route.get(index + 1), PathPlanner.MARGIN, others))) {
            index++;
        }
        Point2 waypoint = route.get(index);
        if (!others.isEmpty() && !planner.clear(here, aim(here, waypoint), 0, others)) {
            avoidAgentsUntil = motor.time() + STUCK_SECONDS;
            if (!replan(here, goal, others(here))) {
                motor.halt();
                return Status.RUNNING; // hemmed in by agents: wait for them to move
            }
            waypoint = route.get(index);
        }
        return send(here, waypoint) ? Status.RUNNING : Status.FAILED;
    }

    private boolean replan(Point2 here, Point2 goal, List<Circle> others) {
        Optional<List<Point2>> planned = planner.plan(here, goal, others);
        if (planned.isEmpty() && !others.isEmpty()) {
            planned = planner.plan(here, goal);
        }
        if (planned.isEmpty()) {
            return false;
        }
        route = new ArrayList<>(planned.get());
        index = 0;
        routeVersion = memory.terrainVersion();
        return true;
    }

    /** Reacts to the answer to the latest move; false when the way keeps being refused. */
    private boolean learnFromLastMove() {
        MoveStatus last = motor.lastMove();
        if (last == null || last == handled || !last.answered()) {
            return true;
        }
        handled = last;
        if (last.rejected()) {
            Obstruction what = Obstruction.of(last.reason());
            if (what == Obstruction.RIVER || what == Obstruction.CASTLE) {
                // Something it cannot have seen: look that way, so that the next perception shows it.
                motor.turnTo(Bearings.headingTowards(last.from(), last.to()));
            }
            if (what.isObstacle()) {
                route = null;
                if (++rejections >= MAX_REJECTIONS) {
                    return false;
                }
            }
        } else if (last.blocked()) {
            route = null;
            avoidAgentsUntil = motor.time() + STUCK_SECONDS;
        }
        return true;
    }

    private boolean stalled(Point2 here) {
        if (here.distance(progressAt) > 0.3) {
            progressAt = here;
            progressTime = motor.time();
            return false;
        }
        if (motor.time() - progressTime > STUCK_SECONDS) {
            progressTime = motor.time();
            return true;
        }
        return false;
    }

    /** The other agents to keep clear of now: near ones always when avoiding, else those right ahead. */
    private List<Circle> others(Point2 here) {
        List<Circle> circles = new ArrayList<>();
        boolean avoiding = motor.time() < avoidAgentsUntil;
        for (SeenAgent agent : memory.agents()) {
            double d = here.distance(agent.position());
            if (d < (avoiding ? 2 * AGENT_LOOKAHEAD : AGENT_LOOKAHEAD)) {
                circles.add(Circle.around(agent.position(), agent.radius() + AGENT_ROOM));
            }
        }
        return circles;
    }

    private boolean stillClear(Point2 here, List<Circle> others) {
        Point2 from = here;
        for (int i = index; i < route.size(); i++) {
            if (!planner.clear(from, route.get(i), 0.05, others)) {
                return false;
            }
            from = route.get(i);
        }
        return true;
    }

    private static Point2 aim(Point2 here, Point2 waypoint) {
        double d = here.distance(waypoint);
        if (d <= MAX_STEP) {
            return waypoint;
        }
        double f = MAX_STEP / d;
        return new Point2(here.x() + (waypoint.x() - here.x()) * f, here.z() + (waypoint.z() - here.z()) * f);
    }

    /** Sends the move towards the waypoint unless one under way will do; false when that very move was just refused. */
    private boolean send(Point2 here, Point2 waypoint) {
        Point2 aim = aim(here, waypoint);
        MoveStatus last = motor.lastMove();
        if (motor.walking() && last != null && !last.rejected() && !last.blocked() && onTheWay(here, last.to(), aim)) {
            return true;
        }
        if (last != null && last.tick() == motor.tick()) {
            return true;
        }
        if (here.distance(aim) < 0.02) {
            return true;
        }
        if (last != null && last.rejected() && Obstruction.of(last.reason()).isObstacle()
                && last.from().distance(here) < 0.05 && last.to().distance(aim) < 0.05) {
            return false; // the plan asks for the move just refused: the map cannot tell why, give up the target
        }
        double off = Math.abs(Bearings.normalise(Bearings.headingTowards(here, aim) - motor.heading()));
        motor.moveTo(aim, off > faceBeyond);
        return true;
    }

    /** Whether walking on to {@code destination} still leads towards {@code aim} for a while. */
    private static boolean onTheWay(Point2 here, Point2 destination, Point2 aim) {
        if (destination.distance(aim) < 0.2) {
            return true;
        }
        double left = here.distance(destination);
        if (left < 1.5) {
            return false;
        }
        double off = Math.abs(Bearings.normalise(Bearings.headingTowards(here, destination)
                - Bearings.headingTowards(here, aim)));
        return off < Math.toRadians(5) && left <= here.distance(aim) + 0.2;
    }
}
