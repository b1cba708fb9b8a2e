package io.orchard.agents.behaviour;

import io.orchard.agents.map.CastleEstimate;
import io.orchard.agents.map.Circle;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Nullable;
import java.util.List;
import java.util.Locale;

/**
 * What an agent that got nowhere commits to ({@link Headway}): one plan, kept until it is carried
 * out or fails, instead of the choice that kept it standing or going back and forth. The plan is
 * the known fruit nearest by planned path (one it has not given up); else the nearest ground not
 * yet seen; else, everything having been seen, a second look: first where the view was poor (at
 * the edge of sight) and around the castle (which may have hidden what lay behind it), then, asked
 * again, everywhere. A fruit whose way is refused is given up, so that the next plan leads
 * elsewhere.
 *
 * <pre>{@code
 * if (committed.active() || headway.stalled()) {
 *     committed.step();  // RUNNING while it has the agent
 * }
 * }</pre>
 */
public final class Commitment {

    /** The longest an agent keeps to the plan, in simulated seconds, before it looks at its choices again. */
    public static final double MAX_SECONDS = 30;

    private static final int PLANNED_CANDIDATES = 6;

    private final WorldMemory memory;
    private final Motor motor;
    private final Navigator navigator;
    private final Harvester harvester;
    private final Explorer explorer;
    private KnownFruit fruit;
    private boolean exploring;
    private double until = Double.NEGATIVE_INFINITY;

    /** A commitment that walks with the harvester's navigator and explores with {@code explorer}. */
    public Commitment(WorldMemory memory, Motor motor, Harvester harvester, Explorer explorer) {
        this.memory = memory;
        this.motor = motor;
        this.harvester = harvester;
        this.navigator = harvester.navigator();
        this.explorer = explorer;
    }

    /** Whether a plan has the agent. */
    public boolean active() {
        return motor.time() < until;
    }

    /** The fruit it committed to; null when none (exploring, or not committed). */
    public @Nullable KnownFruit fruit() {
        return active() ? fruit : null;
    }

    /** Drops the plan (an instruction came). */
    public void drop() {
        until = Double.NEGATIVE_INFINITY;
        fruit = null;
        exploring = false;
    }

    /**
     * One tick of the plan, choosing it first when none has the agent: RUNNING while it does, DONE
     * when the fruit is collected or the ground seen, FAILED when the plan could not be kept.
     */
    public Status step() {
        if (!active()) {
            choose();
        }
        Status status = fruit != null ? harvester.collect(fruit) : explore();
        if (status != Status.RUNNING) {
            drop();
        }
        return status;
    }

    private void choose() {
        navigator.reset();
        until = motor.time() + MAX_SECONDS;
        fruit = nearestByWay();
        exploring = fruit == null;
        if (exploring && explorer.target().isEmpty()) {
            // Seen it all and found nothing: what was missed lies where the view was poor, or behind the castle.
            CastleEstimate castle = memory.castle();
            memory.coverage().lookAgain(castle.located()
                    ? Circle.around(castle.centre().orElseThrow(), 2 * CastleEstimate.MAX_RADIUS) : null);
        }
    }

    private Status explore() {
        if (!harvester.candidates(f -> true).isEmpty()) {
            return Status.DONE; // something to collect came into view: the agent's own choice takes it
        }
        Status status = explorer.step(navigator);
        return status == Status.DONE ? Status.FAILED : status;
    }

    private @Nullable KnownFruit nearestByWay() {
        List<KnownFruit> candidates = harvester.candidates(f -> true);
        KnownFruit best = null;
        double shortest = Double.MAX_VALUE;
        for (KnownFruit candidate : candidates.subList(0, Math.min(PLANNED_CANDIDATES, candidates.size()))) {
            double way = harvester.wayTo(candidate);
            if (way == Double.MAX_VALUE) {
                harvester.giveUp(candidate.id());
            } else if (way < shortest) {
                shortest = way;
                best = candidate;
            }
        }
        return best;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "Commitment[%s]", !active() ? "none"
                : fruit != null ? fruit.id() : "exploring");
    }
}
