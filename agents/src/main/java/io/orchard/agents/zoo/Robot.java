package io.orchard.agents.zoo;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.agents.behaviour.Status;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.Coverage;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.RiverMap;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.function.Predicate;

/**
 * The paper's two-legged robot: grey metal, a visor, straight arms ending in claws. Tall, it
 * reaches fruit on tables and high in the trees, but its claws do not go down to a tomato on the
 * ground.
 *
 * <p>Body: radius 0.5, height 2.2, speed 8; claws reaching 0.8 beyond the body, fruit centres
 * from 0.2 to 2.6 high; sight 60 units over 180 degrees. Model {@code models/Robot.x3d} with the
 * joints LeftHip, LeftKnee, RightHip, RightKnee, LeftShoulder, RightShoulder, LeftClaw,
 * RightClaw, Head and the animations RobotTSWalk and RobotTSGrasp.
 *
 * <h2>Architecture: map building with a planner</h2>
 * A deliberative sense-model-plan-act cycle. It builds a map of everything it perceives (the
 * controller's world memory) and plans on it: a <em>tour</em> of the known fruit it can reach,
 * ordered greedily by planned path length and value (the first leg by A* over the map, the later
 * legs estimated), or, when it knows no fruit, a <em>survey</em> of the frontier point that
 * promises the most unseen ground for the walk. It then executes the plan step by step and plans
 * again when the map changes (new fruit, fruit gone), when a step fails, or every few seconds.
 * An instruction suspends the plan: the controller's errands pursue it, and the robot plans anew
 * once it is done.
 */
public final class Robot extends AgentController {

    private static final double SHOULDER_HEIGHT = 1.67;
    private static final double ARM_LENGTH = 0.84;
    private static final int TOUR_CANDIDATES = 6;
    private static final int TOUR_LENGTH = 4;
    private static final double REPLAN_SECONDS = 8;
    /** The extra cost, in units, of a frontier across the river: the agent's own bank comes first. */
    private static final double ACROSS_THE_RIVER = 60;

    /** A step of the robot's plan. */
    private sealed interface Step permits Fetch, Survey {}

    /** Collect this fruit. */
    private record Fetch(KnownFruit fruit) implements Step {}

    /** Walk to a frontier point to see what is there. */
    private record Survey(Point2 where) implements Step {}

    private final Deque<Step> plan = new ArrayDeque<>();
    private Skills skills;
    private Pose pose;
    private long plannedFruit = -1;
    private double plannedAt = Double.NEGATIVE_INFINITY;
    private double headAngle;
    private boolean clawsOpen;

    /** A robot called Robot. */
    public Robot() {
        this("Robot");
    }

    /** A robot with another name. */
    public Robot(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder()
                .radius(0.5).height(2.2).speed(8)
                .gripper("claw", 0.8, 0.2, 2.6)
                .sight(60, Math.PI)
                .model("models/Robot.x3d", "Robot")
                .joints("LeftHip", "LeftKnee", "RightHip", "RightKnee", "LeftShoulder", "RightShoulder",
                        "LeftClaw", "RightClaw", "Head")
                .walkAnimation(name() + "TSWalk")
                .graspAnimation(name() + "TSGrasp")
                .build();
    }

    @Override
    protected void onRegistered() {
        skills = new Skills(memory(), motor(), planner(), random());
        pose = new Pose(motor());
        skills.harvester.gesture(pose.armsReach(0.6, () -> play(name() + "TSGrasp", 1.5), SHOULDER_HEIGHT,
                ARM_LENGTH, raised -> claws(false)));
    }

    @Override
    protected void decide(Perception perception) {
        pose.update();
        boolean persisting = skills.persisting(instructed());
        if (pursueInstruction()) {
            plan.clear(); // the plan is stale once the instruction is done
            return;
        }
        if (persisting) {
            plan.clear(); // the plan got it nowhere: keep to one step until it is done, then plan anew
            skills.commitment.step();
            return;
        }
        if (plan.isEmpty() || time() - plannedAt >= REPLAN_SECONDS
                || (memory().fruitVersion() != plannedFruit && time() - plannedAt >= 1)) {
            replan();
        }
        execute();
    }

    // ---- planning --------------------------------------------------------------------------

    private void replan() {
        plan.clear();
        plannedAt = time();
        plannedFruit = memory().fruitVersion();
        tour(f -> true, TOUR_LENGTH);
        if (plan.isEmpty()) {
            Point2 frontier = frontier();
            if (frontier != null) {
                plan.add(new Survey(frontier));
            }
        }
    }

    /** Orders up to {@code length} reachable fruit greedily by (path length) / (value). */
    private void tour(Predicate<KnownFruit> wanted, int length) {
        List<KnownFruit> candidates = new ArrayList<>(skills.harvester.candidates(wanted));
        if (candidates.size() > TOUR_CANDIDATES) {
            candidates = new ArrayList<>(candidates.subList(0, TOUR_CANDIDATES));
        }
        Point2 at = position();
        boolean first = true;
        while (!candidates.isEmpty() && plan.size() < length) {
            KnownFruit best = null;
            double bestCost = Double.MAX_VALUE;
            for (KnownFruit fruit : candidates) {
                double way = first ? skills.wayTo(fruit) : at.distance(fruit.ground()) * 1.25;
                if (way == Double.MAX_VALUE) {
                    continue;
                }
                double cost = way / (1 + 0.3 * fruit.points());
                if (cost < bestCost) {
                    bestCost = cost;
                    best = fruit;
                }
            }
            if (best == null) {
                if (first) {
                    candidates.forEach(f -> skills.harvester.giveUp(f.id()));
                }
                return;
            }
            plan.add(new Fetch(best));
            candidates.remove(best);
            at = best.ground();
            first = false;
        }
    }

    /** The unseen point worth most: unseen ground around it for the walk there. */
    private Point2 frontier() {
        Point2 here = position();
        List<Point2> unseen = memory().coverage().unseen();
        if (unseen.isEmpty()) {
            return null;
        }
        RiverMap river = memory().river();
        RiverMap.Side mySide = river.side(here.x(), here.z(), 0);
        List<Point2> nearest = new ArrayList<>(unseen);
        nearest.sort((a, b) -> Double.compare(a.distance(here), b.distance(here)));
        nearest = nearest.subList(0, Math.min(150, nearest.size()));
        double reach = bodyInForce().sight().range() * 0.6;
        for (int attempt = 0; attempt < 4; attempt++) {
            Point2 best = null;
            double bestScore = -1;
            for (Point2 cell : nearest) {
                if (skills.planner.offLimits(cell)) {
                    continue;
                }
                int gain = 0;
                for (Point2 other : unseen) {
                    if (other.distance(cell) < reach) {
                        gain++;
                    }
                }
                double distance = here.distance(cell);
                RiverMap.Side side = river.side(cell.x(), cell.z(), 0);
                if (mySide != RiverMap.Side.UNKNOWN && side != RiverMap.Side.UNKNOWN && side != mySide) {
                    distance += ACROSS_THE_RIVER;
                }
                double score = gain / (distance + 10);
                if (score > bestScore) {
                    bestScore = score;
                    best = cell;
                }
            }
            if (best == null) {
                return null;
            }
            if (skills.planner.plan(here, best).isPresent()) {
                return best;
            }
            memory().coverage().giveUp(best);
            nearest.remove(best);
        }
        return null;
    }

    // ---- acting ----------------------------------------------------------------------------

    private void execute() {
        Step step = plan.peek();
        if (step == null) {
            skills.wanderer.step(skills.navigator);
            return;
        }
        if (step instanceof Survey survey) {
            look(survey.where());
            Status status = skills.navigator.goTo(survey.where(), Coverage.CELL);
            if (status == Status.FAILED) {
                memory().coverage().giveUp(survey.where());
            }
            if (status != Status.RUNNING || memory().coverage().seen(survey.where())) {
                plan.poll();
            }
        } else if (step instanceof Fetch fetch) {
            fetch(fetch);
        }
    }

    private void fetch(Fetch fetch) {
        KnownFruit fruit = fetch.fruit();
        look(fruit.ground());
        claws(position().distance(fruit.ground()) < 3);
        Status status = skills.harvester.collect(fruit);
        if (status != Status.RUNNING) {
            plan.poll();
        }
    }

    /** Turns the head towards a point, when it turned noticeably. */
    private void look(Point2 at) {
        double angle = Math.max(-1.2, Math.min(1.2, Bearings.bearing(position(), heading(), at)));
        if (Math.abs(angle - headAngle) > 0.25) {
            headAngle = angle;
            setJoint("Head", new Rotation(new Vec3(0, 1, 0), angle));
        }
    }

    private void claws(boolean open) {
        if (open != clawsOpen) {
            clawsOpen = open;
            setJoint("LeftClaw", new Rotation(new Vec3(0, 0, 1), open ? 0.5 : 0));
            setJoint("RightClaw", new Rotation(new Vec3(0, 0, 1), open ? -0.5 : 0));
        }
    }
}
