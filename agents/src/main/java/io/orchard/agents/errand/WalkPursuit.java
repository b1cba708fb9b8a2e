package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import java.util.Optional;

/**
 * Walking to a point fixed when the pursuit starts: a few steps forward, back or aside, back to
 * where an earlier instruction was given, or on and on in a compass direction, a stretch at a
 * time, until the world's edge or something the agent cannot pass.
 */
final class WalkPursuit implements Pursuit {

    /** How far "go forward" or "step left" goes: a few body lengths. */
    static final double FEW_STEPS = 4;

    /** One stretch of "go north". */
    private static final double STRETCH = 15;

    private final Kit kit;
    private final Point2 point;
    private final double heading;
    private final boolean backwards;
    private final String arrived;
    /** For a measured walk, what it says when it cannot go the whole way, given how far it went; else null. */
    private java.util.function.DoubleFunction<String> shortOf;
    private Point2 from;
    private Point2 goal;
    private String outcome = "";

    private WalkPursuit(Kit kit, Point2 point, double heading, boolean backwards, String arrived) {
        this.kit = kit;
        this.point = point;
        this.heading = heading;
        this.backwards = backwards;
        this.arrived = arrived;
    }

    /** Walks to a point and stops there. */
    static WalkPursuit to(Kit kit, Point2 point, String arrived) {
        return new WalkPursuit(kit, point, Double.NaN, false, arrived);
    }

    /**
     * Walks to a point so far in a direction, as it was asked; when the way turns out blocked, it says
     * how far it went ({@code shortOf}, given the distance walked) instead of only that it found no way.
     */
    static WalkPursuit measured(Kit kit, Point2 point, String arrived, java.util.function.DoubleFunction<String> shortOf) {
        WalkPursuit walk = new WalkPursuit(kit, point, Double.NaN, false, arrived);
        walk.shortOf = shortOf;
        walk.from = kit.here();
        return walk;
    }

    /** Walks {@code distance} in the direction of {@code heading}; backwards keeps facing the way it faces. */
    static WalkPursuit steps(Kit kit, double heading, boolean backwards, double distance) {
        Point2 end = Bearings.ahead(kit.here(), heading, distance);
        return new WalkPursuit(kit, end, Double.NaN, backwards, kit.speech.moved());
    }

    /** Walks on in the direction of {@code heading} as far as it can. */
    static WalkPursuit on(Kit kit, double heading, String direction) {
        return new WalkPursuit(kit, null, heading, false, kit.speech.asFarAsICan(direction));
    }

    @Override
    public Status step() {
        Point2 here = kit.here();
        if (point != null && backwards) {
            if (goal == null) {
                goal = point;
                kit.motor.moveTo(point, false);
                return Status.RUNNING;
            }
            return kit.motor.walking() ? Status.RUNNING : finish(Status.DONE);
        }
        if (point != null) {
            if (goal == null) {
                goal = point;
                Optional<String> rule = kit.forbidden(point);
                if (rule.isPresent() && !kit.forbidden(here).isPresent()) {
                    kit.standStill();
                    outcome = kit.speech.wontGoThere(rule.get());
                    return Status.FAILED;
                }
            }
            Status status = kit.navigator.goTo(point, 0.8);
            if (status == Status.DONE && kit.motor.walking()) {
                // Near enough to count as there, but the move under way ends at the point itself:
                // stopping now would leave a measured walk short of what was asked.
                return Status.RUNNING;
            }
            return status == Status.RUNNING ? status : finish(status);
        }
        if (goal == null || here.distance(goal) < 2) {
            goal = stretch(here);
            kit.navigator.reset();
            if (goal == null) {
                return finish(Status.DONE);
            }
        }
        Status status = kit.navigator.goTo(goal, 1);
        if (status == Status.FAILED) {
            return finish(Status.DONE); // something it cannot pass: as far as it goes
        }
        return Status.RUNNING;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    private Status finish(Status status) {
        kit.standStill();
        if (status == Status.DONE) {
            outcome = arrived;
        } else {
            outcome = shortOf != null ? shortOf.apply(from.distance(kit.here())) : kit.speech.noWayThere();
        }
        return status;
    }

    /** The end of the next stretch in the heading, inside the world; null at its edge. */
    private Point2 stretch(Point2 here) {
        Bounds bounds = kit.memory.bounds();
        for (double length = STRETCH; length >= 3; length /= 2) {
            Point2 end = Bearings.ahead(here, heading, length);
            if (bounds.contains(end.x(), end.z()) && !kit.planner.offLimits(end) && kit.planner.standable(end, 0.1)) {
                return end;
            }
        }
        return null;
    }
}
