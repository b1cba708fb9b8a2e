package io.orchard.agents.behaviour;

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
 * none is known, wander when everything has been seen. Instructed goals are not its business:
 * the controller's {@link io.orchard.agents.errand.Errands} pursue them, and the forager rests
 * meanwhile.
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
    private KnownFruit target;
    private double chosenAt = Double.NEGATIVE_INFINITY;

    /** A forager for the agent {@code motor} drives, drawing its random choices from {@code random}. */
    public Forager(WorldMemory memory, Motor motor, RandomGenerator random) {
        this(memory, motor, new PathPlanner(memory), random);
    }

    /** A forager that plans its ways with the agent's own {@code planner}, shared with its other behaviours. */
    public Forager(WorldMemory memory, Motor motor, PathPlanner planner, RandomGenerator random) {
        this.memory = memory;
        this.motor = motor;
        this.planner = planner;
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

    /** The fruit it is after; null when none. */
    public @Nullable KnownFruit target() {
        return target;
    }

    /** One tick of autonomy. */
    public void step() {
        forage(fruit -> true);
    }

    /**
     * Forgets its target and route: something else has the agent (an instruction), and when the
     * forager gets it back it will stand elsewhere.
     */
    public void pause() {
        target = null;
        navigator.reset();
        wanderer.reset();
    }

    /**
     * Collects the fruit wanted, exploring and then wandering when none is known.
     */
    private void forage(Predicate<KnownFruit> wanted) {
        if (target != null && (memory.gone(target.id()) || harvester.givenUp(target.id()))
                && !target.id().equals(harvester.current())) {
            target = null;
        }
        if (target == null || motor.time() - chosenAt >= RECHOOSE_SECONDS) {
            choose(wanted);
        }
        if (target != null) {
            Status status = harvester.collect(target);
            if (status != Status.RUNNING) {
                target = null;
            }
            return;
        }
        if (explorer.step(navigator) == Status.DONE) {
            wanderer.step(navigator);
        }
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
        return String.format(Locale.ROOT, "Forager[target=%s]", target == null ? null : target.id());
    }
}
