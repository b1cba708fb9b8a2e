package io.orchard.agents.errand;

import io.orchard.agents.language.Collect;
import io.orchard.agents.language.Cross;
import io.orchard.agents.language.Explore;
import io.orchard.agents.language.Follow;
import io.orchard.agents.language.GoTo;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.LookAt;
import io.orchard.agents.language.LookFor;
import io.orchard.agents.language.Place;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.language.Sequence;
import io.orchard.agents.language.WhenSee;
import io.orchard.agents.map.SeenAgent;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The conditions in force ({@link WhenSee}): for each, the things that fit it that the agent has
 * acted on already. A thing is seen when it is in the agent's latest perception (fruit, agents) or
 * within its sight (trees, tables, bridges, the castle, the river); each is acted on once, except
 * an agent, which is acted on again once it has been out of sight.
 */
final class Watching {

    /** A condition come true: the thing seen, and what to do for it, its words now naming that very thing. */
    record Seen(Known thing, Goal goal) {
    }

    private record Watch(Grounder grounder, Set<String> actedOn) {
    }

    private final Kit kit;
    private final Map<WhenSee, Watch> watches = new LinkedHashMap<>();

    Watching(Kit kit) {
        this.kit = kit;
    }

    /** Watches for what the condition names, grounded from where the agent was told. */
    void watch(WhenSee when, Grounder grounder) {
        watches.put(when, new Watch(grounder, new HashSet<>()));
    }

    /** Stops watching for it. */
    void forget(WhenSee when) {
        watches.remove(when);
    }

    /** The first condition come true now, for the nearest thing not acted on yet; null when none has. */
    @Nullable Seen next() {
        for (Map.Entry<WhenSee, Watch> entry : watches.entrySet()) {
            WhenSee when = entry.getKey();
            Watch watch = entry.getValue();
            List<Known> fits = watch.grounder().fitting(when.what());
            watch.actedOn().removeIf(id -> when.what().kind() == Kind.AGENT && fits.stream()
                    .noneMatch(k -> k.id().equals(id) && inSight(k))); // out of sight: it may be met again
            for (Known thing : fits) {
                if (inSight(thing) && !watch.actedOn().contains(thing.id()) && takeable(thing, when)) {
                    watch.actedOn().add(thing.id());
                    return new Seen(thing, replace(when.then(), when.what(), meaning(thing, when.what())));
                }
            }
        }
        return null;
    }

    /** Whether the agent may and can take the thing, when what it is told to do for it is to take it. */
    private boolean takeable(Known thing, WhenSee when) {
        if (thing.fruit() == null) {
            return true;
        }
        List<Goal> steps = when.then() instanceof Sequence sequence ? sequence.steps() : List.of(when.then());
        boolean taking = steps.stream().anyMatch(step -> step instanceof Collect collect
                && collect.what().equals(when.what()));
        return !taking || (kit.harvester.canReach(thing.fruit()) && kit.memory.conduct().allows(thing.fruit()));
    }

    private boolean inSight(Known thing) {
        if (thing.fruit() != null) {
            return thing.fruit().seenTick() >= kit.memory.tick();
        }
        if (thing.kind() == Kind.AGENT) {
            for (SeenAgent agent : kit.memory.agents()) {
                if (agent.name().equals(thing.id()) && agent.tick() >= kit.memory.tick()) {
                    return true;
                }
            }
            return false;
        }
        Point2 here = kit.here();
        return thing.where().distance(here) <= kit.memory.sight().range() + thing.size();
    }

    /** The words for the very thing seen: "the banana F12", "the tree T3"; the words themselves for the rest. */
    private static Reference meaning(Known thing, Reference words) {
        return thing.kind().hasIds() ? Reference.thing(thing.kind(), thing.id()) : words;
    }

    /** The goal with every reference equal to {@code from} (and every anchor) put as {@code to}. */
    static Goal replace(Goal goal, Reference from, Reference to) {
        if (goal instanceof Sequence sequence) {
            List<Goal> steps = new ArrayList<>();
            sequence.steps().forEach(step -> steps.add(replace(step, from, to)));
            return Sequence.of(steps);
        }
        if (goal instanceof GoTo goTo) {
            return new GoTo(replace(goTo.destination(), from, to));
        }
        if (goal instanceof Cross cross) {
            return new Cross(replace(cross.landmark(), from, to));
        }
        if (goal instanceof Collect collect) {
            return new Collect(replace(collect.what(), from, to), collect.count());
        }
        if (goal instanceof LookAt lookAt) {
            return new LookAt(replace(lookAt.target(), from, to));
        }
        if (goal instanceof LookFor lookFor) {
            return new LookFor(replace(lookFor.what(), from, to));
        }
        if (goal instanceof Explore explore && explore.area() != null) {
            return new Explore(replace(explore.area(), from, to));
        }
        if (goal instanceof Follow follow) {
            return new Follow(replace(follow.agent(), from, to));
        }
        return goal;
    }

    private static Reference replace(Reference reference, Reference from, Reference to) {
        if (reference.equals(from) && (!to.isFruit() || reference.isFruit())) {
            return to;
        }
        Place place = reference.place();
        if (place != null && place.anchor() != null) {
            return reference.withPlace(Place.of(place.relation(), replace(place.anchor(), from, to)));
        }
        return reference;
    }
}
