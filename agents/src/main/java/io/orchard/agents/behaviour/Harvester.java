package io.orchard.agents.behaviour;

import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.Obstruction;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * Approaches a fruit and grasps it. The server grants a grasp when the fruit's centre is within
 * the gripper's heights, no farther on the ground than the body's radius plus the gripper's reach
 * plus the fruit's radius, and within 60 degrees of the heading; so the harvester picks a free
 * spot within that distance, walks there with a {@link Navigator}, faces the fruit, lets a
 * {@link Gesture} bring the gripper to it (joints and the body's grasp animation), and sends the
 * grasp. A failed grasp is tried again from a better spot; after three failures, or when the fruit
 * cannot be reached, the fruit is given up for a while.
 */
public final class Harvester {

    /** How an agent's body reaches for a fruit: joint rotations and animations, for viewers. */
    public interface Gesture {

        /** The agent is about to grasp {@code fruit}: bring the gripper to it. */
        void reach(KnownFruit fruit);

        /** The grasp is over, successful or not: return to rest. */
        default void done(boolean success) {}
    }

    /** How long a fruit stays given up, in simulated seconds. */
    public static final double GIVE_UP_SECONDS = 45;

    /** How much nearer than the exact reach the agent makes sure to stand, for rounding. */
    public static final double SLACK = 0.05;

    private static final double ROUNDING = 0.006;
    private static final int MAX_ATTEMPTS = 3;
    private static final int MAX_SPOT_FAILURES = 3;
    private static final int MAX_REFUSALS = 3;

    private final WorldMemory memory;
    private final Motor motor;
    private final Navigator navigator;
    private final PathPlanner planner;
    private final Map<String, Double> givenUp = new HashMap<>();
    private final List<Point2> badSpots = new ArrayList<>();
    private Gesture gesture = fruit -> { };
    private String current;
    private Point2 spot;
    private long spotVersion = -1;
    private int attempts;
    private int spotFailures;
    private int refusals;
    private GraspStatus handled;
    private MoveStatus refusalSeen;

    /** A harvester that walks with {@code navigator}. */
    public Harvester(WorldMemory memory, Motor motor, Navigator navigator) {
        this.memory = memory;
        this.motor = motor;
        this.navigator = navigator;
        this.planner = navigator.planner();
    }

    /** Sets how the body reaches for fruit. */
    public Harvester gesture(Gesture how) {
        this.gesture = how;
        return this;
    }

    /** The navigator it walks with. */
    public Navigator navigator() {
        return navigator;
    }

    /** The fruit being collected; null when none. */
    public String current() {
        return current;
    }

    /**
     * Whether the gripper reaches the fruit's height (from the ground), with room for perception's
     * rounding to a hundredth: a fruit seen at 1.6 may hang at 1.604.
     */
    public boolean canReach(KnownFruit fruit) {
        Gripper gripper = motor.body().gripper();
        return fruit.height() >= gripper.minHeight() + ROUNDING && fruit.height() <= gripper.maxHeight() - ROUNDING;
    }

    /** The farthest the agent's centre may be from the fruit's on the ground for a grasp. */
    public double reach(KnownFruit fruit) {
        Body body = motor.body();
        return body.radius() + body.gripper().reach() + fruit.radius();
    }

    /** Whether the fruit is within reach of an agent standing at {@code from} (facing it). */
    public boolean inReach(KnownFruit fruit, Point2 from) {
        return canReach(fruit) && from.distance(fruit.ground()) <= reach(fruit) - SLACK;
    }

    /** Whether the fruit was given up recently. */
    public boolean givenUp(String fruitId) {
        Double until = givenUp.get(fruitId);
        return until != null && until > motor.time();
    }

    /** Gives the fruit up for {@link #GIVE_UP_SECONDS}. */
    public void giveUp(String fruitId) {
        givenUp.put(fruitId, motor.time() + GIVE_UP_SECONDS);
        if (fruitId.equals(current)) {
            current = null;
        }
    }

    /**
     * The fruit this agent could collect, nearest first: known, at a height it reaches, not given up,
     * allowed by the rules a person set ({@link io.orchard.agents.map.Conduct}), passing {@code filter}.
     */
    public List<KnownFruit> candidates(Predicate<KnownFruit> filter) {
        Point2 here = motor.position();
        List<KnownFruit> list = new ArrayList<>();
        for (KnownFruit fruit : memory.fruit()) {
            if (canReach(fruit) && !givenUp(fruit.id()) && memory.conduct().allows(fruit) && filter.test(fruit)) {
                list.add(fruit);
            }
        }
        list.sort(Comparator.comparingDouble(f -> f.ground().distance(here)));
        return list;
    }

    /**
     * One tick of collecting {@code fruit}: DONE when it is the agent's, FAILED when it is gone,
     * out of reach or given up, else RUNNING.
     */
    public Status collect(KnownFruit fruit) {
        if (!fruit.id().equals(current)) {
            current = fruit.id();
            spot = null;
            attempts = 0;
            spotFailures = 0;
            refusals = 0;
            badSpots.clear();
        }
        MoveStatus move = motor.lastMove();
        if (move != null && move != refusalSeen && move.rejected() && Obstruction.of(move.reason()).isObstacle()) {
            refusalSeen = move;
            if (++refusals >= MAX_REFUSALS) {
                giveUp(fruit.id()); // the way there keeps being refused: something unseen is in it
                return Status.FAILED;
            }
        }
        GraspStatus grasp = motor.lastGrasp();
        if (grasp != null && grasp.fruit().equals(fruit.id()) && grasp.answered() && grasp != handled) {
            handled = grasp;
            gesture.done(grasp.success());
            if (grasp.success()) {
                current = null;
                return Status.DONE;
            }
            String reason = grasp.reason() == null ? "" : grasp.reason();
            if (reason.contains("taken by") || reason.contains("not in the world")) {
                current = null;
                return Status.FAILED;
            }
            if (reason.contains("gripper reaches")) {
                giveUp(fruit.id()); // out of the gripper's heights: no spot will do
                return Status.FAILED;
            }
            spot = null;
            if (++attempts >= MAX_ATTEMPTS) {
                giveUp(fruit.id());
                return Status.FAILED;
            }
        }
        if (memory.gone(fruit.id()) || !canReach(fruit) || givenUp(fruit.id()) || !memory.conduct().allows(fruit)) {
            current = null;
            return Status.FAILED;
        }
        if (grasp != null && grasp.fruit().equals(fruit.id()) && !grasp.answered()) {
            return Status.RUNNING;
        }
        Point2 here = motor.position();
        if (inReach(fruit, here)) {
            double distance = here.distance(fruit.ground());
            if (distance > 0.02) {
                double facing = Bearings.headingTowards(here, fruit.ground());
                if (Math.abs(Bearings.normalise(facing - motor.heading())) > 0.02) {
                    motor.turnTo(facing);
                }
            }
            gesture.reach(fruit);
            motor.grasp(fruit.id());
            return Status.RUNNING;
        }
        if (spot == null || (spotVersion != memory.terrainVersion() && !planner.standable(spot, 0.05))) {
            spot = spotFor(fruit, here);
            spotVersion = memory.terrainVersion();
            if (spot == null) {
                giveUp(fruit.id());
                return Status.FAILED;
            }
        }
        Status walking = navigator.goTo(spot, 0.1);
        if (walking == Status.FAILED || (walking == Status.DONE && !inReach(fruit, here))) {
            badSpots.add(spot);
            spot = null;
            if (++spotFailures >= MAX_SPOT_FAILURES) {
                giveUp(fruit.id());
                return Status.FAILED;
            }
        }
        return Status.RUNNING;
    }

    /**
     * The length of the planned walk to a spot from which the fruit is within reach: 0 when it is
     * within reach already, {@link Double#MAX_VALUE} when there is no such spot or no way there.
     */
    public double wayTo(KnownFruit fruit) {
        Point2 here = motor.position();
        if (inReach(fruit, here)) {
            return 0;
        }
        Point2 to = spotFor(fruit, here);
        return to == null ? Double.MAX_VALUE
                : planner.plan(here, to).map(path -> PathPlanner.length(here, path)).orElse(Double.MAX_VALUE);
    }

    /** A free spot from which the fruit is within reach, preferring the one nearest to {@code from}; null if none. */
    public Point2 spotFor(KnownFruit fruit, Point2 from) {
        double reach = reach(fruit);
        double radius = motor.body().radius();
        double nearest = radius + fruit.radius() + 0.1;
        double[] distances = fruit.onGround()
                ? new double[] {reach - 0.25, Math.max(0.05, reach - 0.6), Math.max(0.05, reach * 0.4)}
                : new double[] {reach - 0.25, Math.max(Math.min(nearest, reach - 0.25), reach - 0.6)};
        Point2 centre = fruit.ground();
        double towards = Math.atan2(from.z() - centre.z(), from.x() - centre.x());
        Point2 best = null;
        double bestScore = Double.MAX_VALUE;
        for (double d : distances) {
            if (d <= 0) {
                continue;
            }
            for (int k = 0; k < 24; k++) {
                double angle = towards + (k % 2 == 0 ? 1 : -1) * ((k + 1) / 2) * (Math.PI / 12);
                Point2 p = new Point2(centre.x() + d * Math.cos(angle), centre.z() + d * Math.sin(angle));
                if (isBad(p) || !planner.standable(p, 0.1)) {
                    continue;
                }
                double score = from.distance(p) + 0.5 * Math.abs(d - (reach - 0.25));
                if (score < bestScore) {
                    bestScore = score;
                    best = p;
                }
            }
        }
        return best;
    }

    private boolean isBad(Point2 p) {
        for (Point2 bad : badSpots) {
            if (bad.distance(p) < 0.3) {
                return true;
            }
        }
        return false;
    }
}
