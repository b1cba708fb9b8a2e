package io.orchard.agents.behaviour;

import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.function.Predicate;

/**
 * Whether the agent is getting anywhere. Progress is a fruit collected; coming at least
 * {@value #STEP} unit nearer (by the way there on its map, or in a straight line) to the fruit it
 * is taken to want: the nearest of those it wants when it last made progress, kept until the next
 * (or until it is gone); or, while it knows of no fruit it wants, looking at ground it has not
 * seen. An agent that stands still, goes back and forth over the same ground, wanders towards one
 * fruit while another is nearer, or looks about while a fruit it wants waits, makes none: after
 * some seconds without progress it is stalled, and should do something else than what got it
 * nowhere (see {@link Commitment}).
 *
 * <pre>{@code
 * Headway headway = new Headway(memory, motor, harvester::canReach, 5);
 * // once per tick:
 * if (headway.stalled()) { ... }
 * }</pre>
 */
public final class Headway {

    /** How much nearer a fruit must come to count. */
    public static final double STEP = 1;

    private final WorldMemory memory;
    private final Motor motor;
    private final @Nullable PathPlanner planner;
    private final Predicate<KnownFruit> wanted;
    private final double patience;
    private String aim;
    private double aimedAt;
    private double seen = -1;
    private GraspStatus graspSeen;
    private double since = Double.NaN;

    /**
     * A watch over the agent {@code motor} drives.
     *
     * @param wanted   the fruit it collects (say, those its gripper reaches)
     * @param patience the simulated seconds without progress after which it is stalled
     */
    public Headway(WorldMemory memory, Motor motor, Predicate<KnownFruit> wanted, double patience) {
        this(memory, motor, null, wanted, patience);
    }

    /**
     * A watch that measures how near a fruit is by the way there on the map {@code planner} plans
     * on (around the water, over a bridge, around the castle), as an agent that walks around
     * obstacles comes nearer, rather than in a straight line.
     *
     * @param wanted   the fruit it collects (say, those its gripper reaches)
     * @param patience the simulated seconds without progress after which it is stalled
     */
    public Headway(WorldMemory memory, Motor motor, @Nullable PathPlanner planner, Predicate<KnownFruit> wanted,
                   double patience) {
        this.memory = memory;
        this.motor = motor;
        this.planner = planner;
        this.wanted = wanted;
        this.patience = patience;
    }

    /**
     * Takes this tick into account (call it once per tick): true once the agent has made no
     * progress for the patience given, and on every tick after until it makes some.
     */
    public boolean stalled() {
        double now = motor.time();
        if (Double.isNaN(since) || progressed()) {
            since = now;
        }
        return now - since >= patience;
    }

    /** How long the agent has gone without progress, in simulated seconds. */
    public double idleFor() {
        return Double.isNaN(since) ? 0 : motor.time() - since;
    }

    /** Starts counting afresh: something else had the agent (an instruction), so the time does not count. */
    public void reset() {
        since = motor.time();
        aim = null;
    }

    private boolean progressed() {
        boolean progress = false;
        GraspStatus grasp = motor.lastGrasp();
        if (grasp != null && grasp != graspSeen && grasp.answered()) {
            graspSeen = grasp;
            progress = grasp.success();
        }
        Point2 here = motor.position();
        KnownFruit chosen = aim == null ? null : memory.fruit(aim).filter(wanted).orElse(null);
        if (aim != null && chosen == null) {
            progress = true; // the fruit it was making for is gone: what it does next counts afresh
        } else if (chosen != null && distance(here, chosen) <= aimedAt - STEP) {
            progress = true;
        }
        if (chosen == null) {
            choose(here);
        }
        double fraction = memory.coverage().fractionSeen();
        if (fraction > seen) {
            // Looking about is how an agent finds fruit, not what it does while it knows of one.
            progress |= seen >= 0 && aim == null;
            seen = fraction;
        }
        if (progress) {
            choose(here);
        }
        return progress;
    }

    /** The fruit it is taken to want from here on: the nearest of those it wants. */
    private void choose(Point2 here) {
        aim = null;
        aimedAt = Double.POSITIVE_INFINITY;
        for (KnownFruit fruit : memory.fruit()) {
            if (!wanted.test(fruit)) {
                continue;
            }
            double d = distance(here, fruit);
            if (d < aimedAt) {
                aim = fruit.id();
                aimedAt = d;
            }
        }
    }

    private double distance(Point2 here, KnownFruit fruit) {
        return planner == null ? here.distance(fruit.ground()) : planner.walks(here).to(fruit.ground());
    }
}
