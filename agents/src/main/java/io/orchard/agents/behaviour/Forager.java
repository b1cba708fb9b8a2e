package io.orchard.agents.behaviour;

import io.orchard.agents.goal.Goal;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.List;
import java.util.Locale;
import java.util.function.Predicate;
import java.util.random.RandomGenerator;

/**
 * The default autonomy of an agent, put together from the other behaviours: collect the known
 * fruit that is cheapest to reach (by planned path, bigger fruit counting for more), explore when
 * none is known, wander when everything has been seen. It takes instructed goals
 * ({@link #instruct(Goal)}), pursues them first, says when they are done, and returns to its
 * autonomy.
 */
public final class Forager {

    private static final double RECHOOSE_SECONDS = 2;
    private static final int PLANNED_CANDIDATES = 4;

    private final WorldMemory memory;
    private final Motor motor;
    private final PathPlanner planner;
    private final Navigator navigator;
    private final Harvester harvester;
    private final Explorer explorer;
    private final Wanderer wanderer;
    private Goal goal;
    private KnownFruit target;
    private double chosenAt = Double.NEGATIVE_INFINITY;

    /** A forager for the agent {@code motor} drives, drawing its random choices from {@code random}. */
    public Forager(WorldMemory memory, Motor motor, RandomGenerator random) {
        this.memory = memory;
        this.motor = motor;
        this.planner = new PathPlanner(memory);
        this.navigator = new Navigator(memory, motor, planner);
        this.harvester = new Harvester(memory, motor, navigator);
        this.explorer = new Explorer(memory, planner);
        this.wanderer = new Wanderer(memory, random);
    }

    /** The path planner it uses. */
    public PathPlanner planner() {
        return planner;
    }

    /** The navigator it walks with. */
    public Navigator navigator() {
        return navigator;
    }

    /** The harvester it collects with (set its gesture to animate the grasp). */
    public Harvester harvester() {
        return harvester;
    }

    /** The instructed goal being pursued; null in autonomy. */
    public @Nullable Goal goal() {
        return goal;
    }

    /** The fruit it is after; null when none. */
    public @Nullable KnownFruit target() {
        return target;
    }

    /** Takes an instructed goal: {@link Goal.CarryOn} drops the current one, the others replace it. */
    public void instruct(Goal instructed) {
        goal = instructed instanceof Goal.CarryOn ? null : instructed;
        target = null;
        navigator.reset();
        wanderer.reset();
    }

    /** One tick: the instructed goal if there is one, else autonomy. */
    public void step() {
        if (goal instanceof Goal.Stop) {
            if (motor.walking()) {
                motor.halt();
            }
        } else if (goal instanceof Goal.GoTo go) {
            Status status = navigator.goTo(go.target(), 0.5);
            if (status != Status.RUNNING) {
                finish(status == Status.DONE ? "I am there: " + go.describe().substring(6) + "."
                        : "I cannot find a way to " + go.describe().substring(6) + ".");
            }
        } else if (goal instanceof Goal.Collect collect) {
            Predicate<KnownFruit> wanted = fruit -> (collect.kind() == null || fruit.kind() == collect.kind())
                    && (collect.fruitId() == null || fruit.id().equals(collect.fruitId()));
            Status status = forage(wanted);
            if (status == Status.DONE) {
                finish("Done: " + collect.describe() + ".");
            } else if (status == Status.FAILED) {
                finish("I know of no fruit like that I can reach (" + collect.describe() + ").");
            }
        } else if (goal instanceof Goal.Explore) {
            if (explorer.step(navigator) == Status.DONE) {
                finish("I have seen everything I can reach.");
            }
        } else {
            forage(fruit -> true);
        }
    }

    private void finish(String answer) {
        motor.say(answer);
        goal = null;
        target = null;
        navigator.reset();
    }

    /**
     * Collects the fruit wanted, exploring and then wandering when none is known. DONE when one was
     * collected, FAILED when none is known and nothing is left to explore (autonomy then wanders).
     */
    private Status forage(Predicate<KnownFruit> wanted) {
        if (target != null && (memory.gone(target.id()) || harvester.givenUp(target.id()))
                && !target.id().equals(harvester.current())) {
            target = null;
        }
        if (target == null || motor.time() - chosenAt >= RECHOOSE_SECONDS) {
            choose(wanted);
        }
        if (target != null) {
            Status status = harvester.collect(target);
            if (status == Status.DONE) {
                target = null;
                return goal == null ? Status.RUNNING : Status.DONE;
            }
            if (status == Status.FAILED) {
                target = null;
            }
            return Status.RUNNING;
        }
        if (explorer.step(navigator) == Status.DONE) {
            if (goal != null) {
                return Status.FAILED;
            }
            wanderer.step(navigator);
        }
        return Status.RUNNING;
    }

    private void choose(Predicate<KnownFruit> wanted) {
        chosenAt = motor.time();
        Point2 here = motor.position();
        List<KnownFruit> candidates = harvester.candidates(wanted);
        KnownFruit best = null;
        double bestScore = Double.MAX_VALUE;
        for (int i = 0; i < Math.min(PLANNED_CANDIDATES, candidates.size()); i++) {
            KnownFruit fruit = candidates.get(i);
            Point2 spot = harvester.inReach(fruit, here) ? here : harvester.spotFor(fruit, here);
            double length = spot == null ? Double.MAX_VALUE
                    : planner.plan(here, spot).map(p -> PathPlanner.length(here, p)).orElse(Double.MAX_VALUE);
            if (length == Double.MAX_VALUE) {
                harvester.giveUp(fruit.id());
                continue;
            }
            double score = length / (1 + 0.25 * fruit.points());
            if (target != null && fruit.id().equals(target.id())) {
                score *= 0.8; // keep to the current choice unless another is clearly better
            }
            if (score < bestScore) {
                bestScore = score;
                best = fruit;
            }
        }
        target = best;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "Forager[goal=%s, target=%s]", goal, target == null ? null : target.id());
    }
}
