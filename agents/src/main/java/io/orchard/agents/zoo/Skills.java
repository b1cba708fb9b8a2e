package io.orchard.agents.zoo;

import io.orchard.agents.behaviour.Commitment;
import io.orchard.agents.behaviour.Explorer;
import io.orchard.agents.behaviour.Harvester;
import io.orchard.agents.behaviour.Headway;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.Navigator;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.behaviour.Wanderer;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.WorldMemory;
import java.util.random.RandomGenerator;

/** The behaviours an agent of the zoo composes, made once it is registered and has a memory. */
final class Skills {

    /** How long an agent of the zoo goes without progress before it commits to a plan. */
    static final double PATIENCE = 5;

    final WorldMemory memory;
    final Motor motor;
    final PathPlanner planner;
    final Navigator navigator;
    final Harvester harvester;
    final Explorer explorer;
    final Wanderer wanderer;
    final Headway headway;
    final Commitment commitment;

    Skills(WorldMemory memory, Motor motor, PathPlanner planner, RandomGenerator random) {
        this(memory, motor, planner, random, PATIENCE);
    }

    /** Skills for an agent that commits to a plan after {@code patience} seconds without progress. */
    Skills(WorldMemory memory, Motor motor, PathPlanner planner, RandomGenerator random, double patience) {
        this.memory = memory;
        this.motor = motor;
        this.planner = planner;
        this.navigator = new Navigator(memory, motor, planner);
        this.harvester = new Harvester(memory, motor, navigator);
        this.explorer = new Explorer(memory, planner);
        this.wanderer = new Wanderer(memory, random);
        this.headway = new Headway(memory, motor, planner, f -> harvester.canReach(f) && !harvester.givenUp(f.id()),
                patience);
        this.commitment = new Commitment(memory, motor, harvester, explorer);
    }

    /**
     * Takes this tick into account and tells whether the agent must keep to a plan: it got nowhere
     * for {@link #PATIENCE} seconds, or a plan it committed to then still has it. An instruction
     * pursued meanwhile does not count as getting nowhere.
     */
    boolean persisting(boolean instructed) {
        if (instructed) {
            headway.reset();
            commitment.drop();
            return false;
        }
        return headway.stalled() || commitment.active();
    }

    /** The length of the planned way to a spot from which the fruit is in reach; MAX_VALUE when there is none. */
    double wayTo(KnownFruit fruit) {
        return harvester.wayTo(fruit);
    }
}
