package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Collect;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.KnownFruit;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Collecting fruit that fits a reference, one after the other, until {@link Collect#count()} are
 * the agent's or, for "all", until it knows of no more. Each fruit is chosen when the last is
 * done, from what memory holds then (so "the coconut on the table" means a coconut that lies on a
 * table now), and kept until it is collected or lost; while none is known the agent looks for one.
 */
final class Gathering implements Pursuit {

    private final Kit kit;
    private final Collect goal;
    private final Looking looking;
    private KnownFruit fruit;
    private int collected;
    private String outcome = "";

    Gathering(Kit kit, Collect goal) {
        this.kit = kit;
        this.goal = goal;
        this.looking = new Looking(kit, goal.what());
    }

    @Override
    public Status step() {
        if (fruit != null && kit.memory.gone(fruit.id()) && !fruit.id().equals(kit.harvester.current())) {
            fruit = null; // someone else took it
        }
        if (fruit == null) {
            fruit = choose();
            kit.navigator.reset();
            if (fruit != null) {
                kit.mention(Known.fruit(fruit));
            }
        }
        if (fruit == null && collected == 0 && goal.what().id() != null) {
            String why = cannot(goal.what().id());
            if (why != null) {
                outcome = why; // the very fruit meant, known, and out of reach or against a rule
                return Status.FAILED;
            }
        }
        if (fruit == null) {
            if (goal.isAll() && collected > 0) {
                outcome = kit.speech.collectedAndNoMore(collected, goal.what());
                return Status.DONE;
            }
            Status status = looking.step();
            if (status == Status.FAILED) {
                outcome = collected > 0 ? kit.speech.collectedAndFoundNoMore(collected, goal.what()) : looking.failure();
            }
            return status;
        }
        Status status = kit.harvester.collect(fruit);
        if (status == Status.DONE) {
            collected++;
            KnownFruit taken = fruit;
            fruit = null;
            if (!goal.isAll() && collected >= goal.count()) {
                outcome = collected == 1 ? kit.speech.pickedUp(taken.kind(), taken.id())
                        : kit.speech.collectedLast(collected, taken.kind(), taken.id());
                return Status.DONE;
            }
            kit.motor.say(kit.speech.got(taken.kind(), taken.id(), goal.isAll() ? -1 : goal.count() - collected));
        } else if (status == Status.FAILED) {
            fruit = null; // out of reach after all: another one
        }
        return Status.RUNNING;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    /** Why the agent cannot take the fruit of this id it knows of; null when it can, or does not know it. */
    private String cannot(String id) {
        KnownFruit known = kit.memory.fruit(id).orElse(null);
        if (known == null) {
            return null;
        }
        if (!kit.harvester.canReach(known)) {
            return kit.speech.tooHigh(known.kind(), id, known.height(), kit.motor.body().gripper());
        }
        return kit.rule(known).map(rule -> kit.speech.wontPickUp(known.kind(), id, rule)).orElse(null);
    }

    /** The fruit to go for: one that fits the words now and that the gripper reaches. */
    private KnownFruit choose() {
        Reference what = goal.what();
        List<Known> fits = kit.grounder.select(what, kit.grounder.fitting(what));
        Set<String> ids = new HashSet<>();
        fits.forEach(k -> ids.add(k.id()));
        List<KnownFruit> reachable = kit.harvester.candidates(f -> ids.contains(f.id()));
        if (reachable.isEmpty()) {
            return null;
        }
        if (what.distance() == Reference.Distance.FARTHEST) {
            return reachable.get(reachable.size() - 1);
        }
        return reachable.get(0);
    }
}
