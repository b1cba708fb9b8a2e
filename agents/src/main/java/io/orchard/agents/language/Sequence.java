package io.orchard.agents.language;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * Several goals, one after the other: "go to the castle and then pick up a tomato", "fetch me the
 * small banana first, then explore". The agent pursues each step until it is reached or cannot
 * be, then the next. Steps are never sequences themselves.
 *
 * @param steps the goals in the order to pursue them; at least two, none a sequence
 */
public record Sequence(List<Goal> steps) implements Goal {

    /** @throws IllegalArgumentException when there are fewer than two steps or a step is a sequence */
    /**
     * Checks the components and keeps its own copy of the lists; a bad value is refused with an exception that
     * names it.
     */
    public Sequence {
        steps = List.copyOf(steps);
        if (steps.size() < 2) {
            throw new IllegalArgumentException("a sequence needs at least two steps, was given " + steps.size());
        }
        for (Goal step : steps) {
            if (step instanceof Sequence) {
                throw new IllegalArgumentException("a step must not be a sequence; use Sequence.of to flatten");
            }
        }
    }

    /**
     * The goal of doing these goals in order: the goal itself when there is one, a flat sequence
     * when there are several (the steps of nested sequences are taken in their place).
     *
     * @throws IllegalArgumentException when there are no goals
     */
    public static Goal of(List<? extends Goal> goals) {
        List<Goal> flat = new ArrayList<>();
        for (Goal goal : goals) {
            Objects.requireNonNull(goal, "goal");
            if (goal instanceof Sequence sequence) {
                flat.addAll(sequence.steps());
            } else {
                flat.add(goal);
            }
        }
        if (flat.isEmpty()) {
            throw new IllegalArgumentException("a sequence of no goals is no goal");
        }
        return flat.size() == 1 ? flat.get(0) : new Sequence(flat);
    }

    /** The goal of doing these goals in order; see {@link #of(List)}. */
    public static Goal of(Goal... goals) {
        return of(List.of(goals));
    }
}
