package io.orchard.agents.behaviour;

import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.CastleEstimate;
import io.orchard.agents.map.Circle;
import io.orchard.agents.map.Coverage;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * Heads for what the memory has not seen, where the most comes into view for the walk: of the
 * cells of the {@link Coverage} not yet looked at, the one with the least (walk + {@value #OFFSET})
 * / (unseen cells within sight of it)<sup>{@value #MASS_EXPONENT}</sup>. The walk is the shortest
 * on the map to a point from which the cell is within sight ({@link WalkingField}: around the
 * water, over a bridge, around the castle), a little longer for a cell behind the agent. Between
 * cells near at hand the walk decides; between far ones, the unseen ground around them, where the
 * fruit not yet seen most likely lies. A cell across the river is looked at from the bank when it
 * can be, walked to over a bridge when it cannot; a cell behind the castle, once the agent knows
 * where the castle stands, from a side it is not hidden on. The agent walks to that point, faces the cell
 * there if it is not yet in view, and gives the cell up when there is no way to it or it still is
 * not seen; it chooses afresh when something else had it meanwhile.
 *
 * <p>So the agent keeps seeing new ground as it goes, rather than crossing ground it has seen for
 * a cell far away: a flat cost for crossing the river, as it had before, sent it along its own
 * bank's edge for a last corner while the other bank, all its fruit with it, waited.
 */
public final class Explorer {

    /** How much nearer than the range at which the coverage counts a cell as seen the agent goes. */
    static final double SPARE = 1.5;

    /** What having to turn right round adds to a walk, in units: ahead comes first when walks are alike. */
    static final double TURN_COST = 4;

    /**
     * What every walk is counted longer by, in units, before it is divided by the unseen ground
     * it shows: so that between near cells the walk decides, between far ones the ground.
     */
    static final double OFFSET = 10;

    /** How much the unseen ground around a cell counts: its number of cells to this power. */
    static final double MASS_EXPONENT = 0.5;

    /** How near the point to walk to is near enough. */
    private static final double ARRIVED = 1;

    /** How many ticks it faces a cell from there before giving it up. */
    private static final int LOOKS = 3;

    private final WorldMemory memory;
    private final PathPlanner planner;
    private Point2 target;
    private Point2 viewpoint;
    private int looks;
    private long lastStep = Long.MIN_VALUE;

    /** An explorer of the world {@code memory} remembers, on the map {@code planner} plans on. */
    public Explorer(WorldMemory memory, PathPlanner planner) {
        this.memory = memory;
        this.planner = planner;
    }

    /** The centre of the cell being headed for; empty when everything has been seen (or given up). */
    public Optional<Point2> target() {
        if (target != null && !memory.coverage().seen(target)) {
            return Optional.of(target);
        }
        choose();
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
        if (memory.tick() > lastStep + 1) {
            target = null; // something else had the agent meanwhile: from where it is now, another cell may come first
        }
        lastStep = memory.tick();
        for (int attempt = 0; attempt < 3; attempt++) {
            Optional<Point2> next = target();
            if (next.isEmpty()) {
                return Status.DONE;
            }
            Status status = memory.position().distance(viewpoint) <= ARRIVED ? Status.DONE
                    : navigator.goTo(viewpoint, ARRIVED);
            if (status == Status.DONE && ++looks > LOOKS) {
                status = Status.FAILED; // it stood there facing the cell and still does not see it
            }
            if (status == Status.FAILED) {
                giveUp();
                navigator.reset();
                continue;
            }
            if (status == Status.DONE) {
                navigator.face(next.get());
            }
            return Status.RUNNING;
        }
        return Status.RUNNING;
    }

    private void choose() {
        target = null;
        viewpoint = null;
        looks = 0;
        Point2 here = memory.position();
        double heading = memory.heading();
        double range = memory.sight().range() * Coverage.RANGE_SHARE - SPARE;
        WalkingField field = planner.walks(here);
        Circle hiding = memory.castle().located()
                ? Circle.around(memory.castle().centre().orElseThrow(), CastleEstimate.CORE_RADIUS) : null;
        Coverage coverage = memory.coverage();
        List<Candidate> candidates = new ArrayList<>();
        for (Point2 cell : coverage.unseen()) {
            double nearest = Math.max(0, here.distance(cell) - range - 2 * WalkingField.CELL);
            double weight = Math.pow(coverage.unseenWithin(cell, range), MASS_EXPONENT);
            candidates.add(new Candidate(cell, weight, (nearest + OFFSET) / weight));
        }
        // No walk to a cell's view is shorter than the straight way to within range of it (less a cell's slack).
        candidates.sort(Comparator.comparingDouble(Candidate::bound));
        double best = Double.POSITIVE_INFINITY;
        for (Candidate candidate : candidates) {
            if (candidate.bound() >= best) {
                break;
            }
            WalkingField.Viewpoint view = field.nearestWithin(candidate.cell(), range, hiding);
            if (view == null) {
                continue; // no known way: perhaps once a bridge is seen
            }
            double turn = TURN_COST * Math.abs(Bearings.bearing(here, heading, candidate.cell())) / Math.PI;
            double score = (view.walk() + turn + OFFSET) / candidate.weight();
            if (score < best) {
                best = score;
                target = candidate.cell();
                viewpoint = view.at();
            }
        }
    }

    private record Candidate(Point2 cell, double weight, double bound) {}
}
