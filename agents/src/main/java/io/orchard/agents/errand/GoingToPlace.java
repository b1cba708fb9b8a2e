package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.GoTo;
import io.orchard.agents.language.Place;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Point2;
import java.util.function.Predicate;

/**
 * Going into an area: near the castle, to the other side of the river, north of the castle, to
 * the north. The area's landmark is grounded when it is needed; the pursuit is done as soon as the
 * agent stands in the area. The other side of the river is reached by a bridge.
 */
final class GoingToPlace implements Pursuit {

    /** How far into a compass area ("north of the castle") the agent walks. */
    private static final double INTO = 12;

    private final Kit kit;
    private final Reference area;
    private final Place place;
    private Pursuit way;
    private String outcome = "";

    GoingToPlace(Kit kit, Reference area) {
        this.kit = kit;
        this.area = area;
        this.place = area.place();
    }

    @Override
    public Status step() {
        Predicate<Known> inside = kit.grounder.where(place);
        Point2 here = kit.here();
        boolean there = inside.test(Known.standing(here));
        if (there) {
            kit.standStill();
            outcome = kit.speech.wentTo(area);
            return Status.DONE;
        }
        if (way == null) {
            way = way(here);
        }
        Status status = way.step();
        if (status != Status.RUNNING) {
            outcome = status == Status.DONE ? kit.speech.wentTo(area) : way.outcome();
        }
        return status;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    private Pursuit way(Point2 here) {
        Reference anchor = place.anchor();
        Place.Relation relation = place.relation();
        if (anchor == null) {
            double heading = relation.sector() == null ? kit.grounder.sideHeading(relation)
                    : Turning.heading(relation.sector());
            return WalkPursuit.to(kit, Bearings.ahead(kit.grounder.toldAt(), heading, INTO), "");
        }
        boolean river = anchor.kind() == Kind.RIVER || anchor.kind() == Kind.BRIDGE;
        if (river && (relation == Place.Relation.BEYOND || relation == Place.Relation.THIS_SIDE_OF)) {
            return new Crossing(kit, anchor.kind() == Kind.BRIDGE ? anchor : Reference.to(Kind.BRIDGE), null);
        }
        if (relation.sector() != null || relation == Place.Relation.BEYOND) {
            return new Beside(anchor);
        }
        return new GoingTo(kit, anchor, null);
    }

    /** Walks to a point on the named side of the anchor, once the anchor is known. */
    private final class Beside implements Pursuit {
        private final Reference anchor;
        private final Looking looking;
        private WalkPursuit walk;

        Beside(Reference anchor) {
            this.anchor = anchor;
            this.looking = new Looking(kit, anchor);
        }

        @Override
        public Status step() {
            if (walk == null) {
                Grounding grounding = kit.grounder.ground(anchor);
                Known known = grounding instanceof Grounding.Found found ? found.chosen()
                        : grounding instanceof Grounding.Ambiguous ambiguous ? ambiguous.choices().get(0) : null;
                if (known == null) {
                    return looking.step();
                }
                Point2 here = kit.here();
                double heading = place.relation().sector() != null ? Turning.heading(place.relation().sector())
                        : Bearings.headingTowards(here, known.where());
                walk = WalkPursuit.to(kit, Bearings.ahead(known.where(), heading, known.size() + INTO), "");
            }
            return walk.step();
        }

        @Override
        public String outcome() {
            return walk == null ? looking.failure() : walk.outcome();
        }
    }
}
