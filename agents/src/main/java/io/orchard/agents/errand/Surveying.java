package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Place;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.Coverage;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.Comparator;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * Exploring: anywhere, until everything reachable has been seen; or an area (the forest, the other
 * side of the river, near the castle), walking to the unseen parts of it nearest first, until it
 * has been looked over. An area whose landmark is not known yet is looked for first.
 */
final class Surveying implements Pursuit {

    private final Kit kit;
    private final Reference area;
    private final Looking looking;
    private Point2 cell;
    private String outcome = "";

    Surveying(Kit kit, @Nullable Reference area) {
        this.kit = kit;
        this.area = area;
        this.looking = area == null ? null : new Looking(kit, area);
    }

    @Override
    public Status step() {
        if (area == null) {
            if (kit.explorer.step(kit.navigator) == Status.DONE) {
                outcome = kit.speech.seenEverything();
                return Status.DONE;
            }
            return Status.RUNNING;
        }
        Predicate<Known> inside = inside();
        if (inside == null) {
            Status status = looking.step();
            if (status == Status.FAILED) {
                outcome = looking.failure();
            }
            return status;
        }
        for (int attempt = 0; attempt < 3; attempt++) {
            if (cell == null || kit.memory.coverage().seen(cell)) {
                Optional<Point2> next = next(inside);
                if (next.isEmpty()) {
                    outcome = kit.speech.lookedOver(area);
                    return Status.DONE;
                }
                cell = next.get();
                kit.navigator.reset();
            }
            Status status = kit.navigator.goTo(cell, Coverage.CELL / 2);
            if (status == Status.RUNNING) {
                return status;
            }
            kit.memory.coverage().giveUp(cell); // stood there, or cannot get there: done with it
            cell = null;
        }
        return Status.RUNNING;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    /** Whether a point is in the area; null while its landmark is not known. */
    private Predicate<Known> inside() {
        if (area.kind() == Reference.Kind.PLACE) {
            Reference anchor = area.place().anchor();
            if (anchor != null && kit.grounder.fitting(anchor).isEmpty()) {
                return null;
            }
            return kit.grounder.where(area.place());
        }
        Grounding grounding = kit.grounder.ground(area);
        if (grounding instanceof Grounding.Unknown) {
            return null;
        }
        if (area.kind() == Reference.Kind.FOREST) {
            return kit.grounder.where(Place.of(Place.Relation.NEAR, area));
        }
        Known known = grounding instanceof Grounding.Found found ? found.chosen()
                : ((Grounding.Ambiguous) grounding).choices().get(0);
        return k -> k.where().distance(known.where()) <= known.size() + Grounder.NEAR;
    }

    private Optional<Point2> next(Predicate<Known> inside) {
        Point2 here = kit.here();
        return kit.memory.coverage().unseen().stream()
                .filter(p -> !kit.planner.offLimits(p) && inside.test(Known.standing(p)))
                .min(Comparator.comparingDouble(p -> p.distance(here)));
    }
}
