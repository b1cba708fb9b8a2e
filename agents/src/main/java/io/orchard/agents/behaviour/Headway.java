package io.orchard.agents.behaviour;

import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Predicate;

/**
 * Whether the agent is getting anywhere. Progress is a fruit collected, coming at least
 * {@value #STEP} unit nearer to a fruit it wants than it has been since its last fruit, or looking
 * at ground it has not seen. An agent that stands still, or goes back and forth over the same
 * ground, makes none: after some seconds without progress it is stalled, and should do something
 * else than what got it nowhere (see {@link Commitment}).
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
    private final Predicate<KnownFruit> wanted;
    private final double patience;
    private final Map<String, Double> nearest = new HashMap<>();
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
        this.memory = memory;
        this.motor = motor;
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
        nearest.clear();
    }

    private boolean progressed() {
        boolean progress = false;
        GraspStatus grasp = motor.lastGrasp();
        if (grasp != null && grasp != graspSeen && grasp.answered()) {
            graspSeen = grasp;
            if (grasp.success()) {
                nearest.clear(); // a new errand: nearness counts from here
                progress = true;
            }
        }
        double fraction = memory.coverage().fractionSeen();
        if (fraction > seen) {
            progress |= seen >= 0;
            seen = fraction;
        }
        Point2 here = motor.position();
        for (KnownFruit fruit : memory.fruit()) {
            if (!wanted.test(fruit)) {
                continue;
            }
            double d = here.distance(fruit.ground());
            Double before = nearest.get(fruit.id());
            if (before == null || d <= before - STEP) {
                nearest.put(fruit.id(), d);
                progress |= before != null;
            }
        }
        return progress;
    }
}
