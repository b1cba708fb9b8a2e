package io.orchard.agents.zoo;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.goal.Goal;
import io.orchard.agents.map.KnownFruit;
import io.orchard.protocol.value.Point2;
import java.util.List;
import java.util.Locale;
import java.util.function.Predicate;

/**
 * The mechanics of carrying out an instructed goal with the zoo's skills, shared by the agents;
 * when and how an agent pursues it is its architecture's business. When the errand is over,
 * {@link #answer()} says how it went.
 */
final class Errand {

    private final Skills skills;
    private KnownFruit fruit;
    private String answer = "";

    Errand(Skills skills) {
        this.skills = skills;
    }

    /** What to tell the person once the errand is over. */
    String answer() {
        return answer;
    }

    /** Forgets the fruit chosen, for a new errand. */
    void reset() {
        fruit = null;
        skills.navigator.reset();
    }

    /** One tick of pursuing {@code goal}: DONE or FAILED when over, else RUNNING. */
    Status pursue(Goal goal) {
        if (goal instanceof Goal.Stop) {
            if (skills.motor.walking()) {
                skills.motor.halt();
            }
            return Status.RUNNING;
        }
        if (goal instanceof Goal.GoTo go) {
            Status status = skills.navigator.goTo(go.target(), 0.5);
            answer = status == Status.DONE ? "I am there: " + where(go.target()) + "."
                    : "I cannot find a way to " + where(go.target()) + ".";
            return status;
        }
        if (goal instanceof Goal.Explore) {
            answer = "I have seen all I can reach.";
            return skills.explorer.step(skills.navigator) == Status.DONE ? Status.DONE : Status.RUNNING;
        }
        if (goal instanceof Goal.Collect collect) {
            return collect(collect);
        }
        return Status.DONE;
    }

    private Status collect(Goal.Collect collect) {
        Predicate<KnownFruit> wanted = f -> (collect.kind() == null || f.kind() == collect.kind())
                && (collect.fruitId() == null || f.id().equals(collect.fruitId()));
        if (fruit != null && (skills.memory.gone(fruit.id()) && !fruit.id().equals(skills.harvester.current()))) {
            fruit = null;
        }
        if (fruit == null) {
            List<KnownFruit> candidates = skills.harvester.candidates(wanted);
            for (KnownFruit candidate : candidates.subList(0, Math.min(3, candidates.size()))) {
                if (skills.wayTo(candidate) < Double.MAX_VALUE) {
                    fruit = candidate;
                    break;
                }
            }
        }
        if (fruit == null) {
            answer = "I know of no fruit I can reach for '" + collect.describe() + "'.";
            return skills.explorer.step(skills.navigator) == Status.DONE ? Status.FAILED : Status.RUNNING;
        }
        Status status = skills.harvester.collect(fruit);
        if (status == Status.DONE) {
            answer = "Done: I collected the " + fruit.kind().wireName() + " " + fruit.id() + ".";
            fruit = null;
            return Status.DONE;
        }
        if (status == Status.FAILED) {
            fruit = null; // another one, next tick
        }
        return Status.RUNNING;
    }

    private static String where(Point2 p) {
        return String.format(Locale.ROOT, "(%.1f, %.1f)", p.x(), p.z());
    }
}
