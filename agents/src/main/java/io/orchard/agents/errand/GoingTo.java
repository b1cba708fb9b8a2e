package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.map.SeenAgent;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.Optional;

/**
 * Going to an object: a tree, a table, a fruit, the castle, the river, a bridge, the forest or an
 * agent. The object is grounded when the pursuit starts (or given, when the person chose it from a
 * question) and kept; while none is known the agent looks for one. It is reached when the agent
 * stands next to it.
 */
final class GoingTo implements Pursuit {

    private final Kit kit;
    private final Reference destination;
    private final Looking looking;
    private Known target;
    private String outcome = "";

    GoingTo(Kit kit, Reference destination, @Nullable Known chosen) {
        this.kit = kit;
        this.destination = destination;
        this.looking = new Looking(kit, destination);
        this.target = chosen;
    }

    @Override
    public Status step() {
        if (target == null) {
            Grounding grounding = kit.grounder.ground(destination);
            if (grounding instanceof Grounding.Found found) {
                target = found.chosen();
            } else if (grounding instanceof Grounding.Ambiguous ambiguous) {
                target = ambiguous.choices().get(0); // it became ambiguous while looking: the nearest will do
            } else {
                Status status = looking.step();
                if (status == Status.FAILED) {
                    outcome = looking.failure();
                }
                return status;
            }
            kit.navigator.reset();
            kit.mention(target);
            Optional<String> rule = target.kind() == Kind.AGENT ? Optional.empty() : kit.forbidden(target.where());
            if (rule.isPresent()) {
                outcome = kit.speech.wontGoTo(target, rule.get());
                return Status.FAILED;
            }
        }
        Point2 here = kit.here();
        Point2 where = whereNow();
        double radius = kit.memory.radius();
        Status status;
        if (target.kind() == Kind.CASTLE) {
            if (here.distance(where) <= Grounder.CASTLE_SIZE + 6) {
                return done();
            }
            Point2 spot = towards(where, here, Grounder.CASTLE_SIZE + 4);
            status = kit.navigator.goTo(spot, 2);
            if (status == Status.FAILED && here.distance(where) <= Grounder.CASTLE_SIZE + 12) {
                return done(); // the castle's wall is nearer than estimated
            }
        } else if (target.kind() == Kind.RIVER) {
            if (here.distance(where) <= 4) {
                return done();
            }
            status = kit.navigator.goTo(towards(where, here, 2.5), 1.5);
        } else if (target.kind() == Kind.BRIDGE) {
            status = kit.navigator.goTo(target.bridge().entryNear(here), 1.5);
        } else {
            double size = target.kind() == Kind.TREE ? Math.min(target.size(), 1.5) : target.size();
            if (here.distance(where) <= size + radius + 1.2) {
                return done();
            }
            Optional<Point2> spot = kit.besides(where, size);
            if (spot.isEmpty()) {
                outcome = kit.speech.noFreeSpot(target);
                return Status.FAILED;
            }
            status = kit.navigator.goTo(spot.get(), target.kind() == Kind.AGENT ? 1.5 : 0.8);
        }
        if (status == Status.DONE) {
            return done();
        }
        if (status == Status.FAILED) {
            outcome = kit.speech.noWayTo(target);
        }
        return status;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    private Status done() {
        kit.standStill();
        outcome = kit.speech.imAt(target);
        return Status.DONE;
    }

    /** Where the target is now: agents move, the castle's estimate sharpens. */
    private Point2 whereNow() {
        if (target.kind() == Kind.AGENT) {
            for (SeenAgent agent : kit.memory.agents()) {
                if (agent.name().equals(target.id())) {
                    target = Known.of(Kind.AGENT, agent.name(), agent.position(), agent.radius());
                }
            }
        } else if (target.kind() == Kind.CASTLE) {
            kit.grounder.castle().ifPresent(c -> target = Known.of(Kind.CASTLE, "castle", c, Grounder.CASTLE_SIZE));
        }
        return target.where();
    }

    /** The point {@code distance} from {@code centre} in the direction of {@code from}. */
    static Point2 towards(Point2 centre, Point2 from, double distance) {
        double d = centre.distance(from);
        if (d < 1e-6) {
            return from;
        }
        return new Point2(centre.x() + (from.x() - centre.x()) / d * distance,
                centre.z() + (from.z() - centre.z()) / d * distance);
    }
}
