package io.orchard.agents.behaviour;

import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.Coverage;
import io.orchard.agents.map.RiverMap;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.Optional;

/**
 * Heads for what the memory has not seen: the nearest cell of the {@link Coverage} not yet looked
 * at, preferring cells ahead and on the agent's own side of the river, and gives a cell up when
 * there is no way to it.
 */
public final class Explorer {

    /** The extra cost, in units, of a cell across the river: the agent's own bank comes first. */
    public static final double ACROSS_THE_RIVER = 60;

    private final WorldMemory memory;
    private final PathPlanner planner;
    private Point2 target;

    /** An explorer of the world {@code memory} remembers, planning with {@code planner}. */
    public Explorer(WorldMemory memory, PathPlanner planner) {
        this.memory = memory;
        this.planner = planner;
    }

    /** The cell centre being headed for; empty when everything has been seen (or given up). */
    public Optional<Point2> target() {
        Coverage coverage = memory.coverage();
        if (target != null && !coverage.seen(target)) {
            return Optional.of(target);
        }
        target = choose();
        return Optional.ofNullable(target);
    }

    /** Gives up the current target: there is no way to it. */
    public void giveUp() {
        if (target != null) {
            memory.coverage().giveUp(target);
            target = null;
        }
    }

    /**
     * One tick of exploring with {@code navigator}: RUNNING while there is something left to see,
     * DONE when there is nothing.
     */
    public Status step(Navigator navigator) {
        for (int attempt = 0; attempt < 3; attempt++) {
            Optional<Point2> next = target();
            if (next.isEmpty()) {
                return Status.DONE;
            }
            Status status = navigator.goTo(next.get(), Coverage.CELL / 2);
            if (status == Status.FAILED) {
                giveUp();
                navigator.reset();
                continue;
            }
            if (status == Status.DONE) {
                memory.coverage().giveUp(next.get()); // stood there: whatever is there is seen
                target = null;
            }
            return Status.RUNNING;
        }
        return Status.RUNNING;
    }

    private Point2 choose() {
        Point2 here = memory.position();
        double heading = memory.heading();
        RiverMap river = memory.river();
        RiverMap.Side mySide = river.side(here.x(), here.z(), 0);
        Point2 best = null;
        double bestScore = Double.MAX_VALUE;
        for (Point2 cell : memory.coverage().unseen()) {
            if (planner.offLimits(cell)) {
                memory.coverage().giveUp(cell);
                continue;
            }
            double score = here.distance(cell) * (1 + 0.4 * Math.abs(Bearings.bearing(here, heading, cell)) / Math.PI);
            RiverMap.Side side = river.side(cell.x(), cell.z(), 0);
            if ((mySide == RiverMap.Side.LOW || mySide == RiverMap.Side.HIGH)
                    && (side == RiverMap.Side.LOW || side == RiverMap.Side.HIGH) && side != mySide) {
                score += ACROSS_THE_RIVER;
            }
            if (score < bestScore) {
                bestScore = score;
                best = cell;
            }
        }
        return best;
    }
}
