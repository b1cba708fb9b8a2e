package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.KnownBridge;
import io.orchard.agents.map.RiverMap;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.Comparator;
import java.util.Optional;

/**
 * Crossing the river by a bridge: the bridge the person chose or named ("the nearest bridge"), else
 * the one of the shortest way. The agent walks onto it at its near end, and over it to a point a few
 * steps beyond its far end;
 * the crossing is done when it stands on the other bank from the one it started on. A bridge not
 * yet known is looked for first.
 */
final class Crossing implements Pursuit {

    /** How far past the far end of the bridge the agent walks, to stand clear of it on the bank. */
    private static final double BEYOND = 3;

    private final Kit kit;
    private final Reference landmark;
    private final Looking looking;
    private KnownBridge bridge;
    private RiverMap.Side from;
    private Point2 destination;
    private Point2 entry;
    private boolean onto;
    private String outcome = "";

    Crossing(Kit kit, Reference landmark, @Nullable Known chosen) {
        this.kit = kit;
        this.landmark = landmark.kind() == Reference.Kind.BRIDGE ? landmark : Reference.to(Reference.Kind.BRIDGE);
        this.looking = new Looking(kit, this.landmark);
        this.bridge = chosen == null ? null : chosen.bridge();
    }

    @Override
    public Status step() {
        Point2 here = kit.here();
        if (from == null) {
            RiverMap.Side side = kit.grounder.side(here);
            if (side == RiverMap.Side.LOW || side == RiverMap.Side.HIGH) {
                from = side;
            }
        }
        if (bridge == null) {
            bridge = choose(here);
            if (bridge == null) {
                Status status = looking.step();
                if (status == Status.FAILED) {
                    outcome = looking.failure();
                }
                return status;
            }
            kit.navigator.reset();
        }
        if (destination == null) {
            Point2 pastA = past(bridge.entryB(), bridge.entryA());
            Point2 pastB = past(bridge.entryA(), bridge.entryB());
            if (from != null && sideOf(pastA) != from && sideOf(pastA) != RiverMap.Side.UNKNOWN) {
                destination = pastA;
            } else if (from != null && sideOf(pastB) != from && sideOf(pastB) != RiverMap.Side.UNKNOWN) {
                destination = pastB;
            } else {
                destination = here.distance(pastA) >= here.distance(pastB) ? pastA : pastB;
            }
            entry = destination == pastA ? bridge.entryB() : bridge.entryA();
            kit.mention(new Known(Reference.Kind.BRIDGE, bridge.id(), bridge.middle(), bridge.length() / 2, null,
                    bridge));
            Optional<String> rule = kit.forbidden(destination);
            if (rule.isPresent()) {
                outcome = kit.speech.wontCross(rule.get());
                return Status.FAILED;
            }
        }
        if (!onto) {
            // onto the deck first: the shortest way to the far bank may lead over the other bridge
            Status toEntry = kit.navigator.goTo(entry, 1.5);
            onto = toEntry == Status.DONE || bridge.covers(here, 0, 0.5);
            if (toEntry == Status.FAILED) {
                outcome = kit.speech.noWayOnto(bridge.id());
                return Status.FAILED;
            }
            if (!onto) {
                return Status.RUNNING;
            }
            kit.navigator.reset();
        }
        Status status = kit.navigator.goTo(destination, 1.2);
        if (status == Status.FAILED) {
            outcome = kit.speech.noWayOver(bridge.id());
            return status;
        }
        RiverMap.Side now = kit.grounder.side(here);
        if (status == Status.DONE || (from != null && now != from && now != RiverMap.Side.WATER
                && now != RiverMap.Side.UNKNOWN && here.distance(bridge.middle()) > bridge.length() / 2 + 1)) {
            kit.standStill();
            outcome = kit.speech.otherSide(bridge.id());
            return Status.DONE;
        }
        return Status.RUNNING;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    private KnownBridge choose(Point2 here) {
        if (landmark.distance() != null || landmark.size() != null || landmark.place() != null) {
            Grounding grounding = kit.grounder.ground(landmark);
            return grounding instanceof Grounding.Found found ? found.chosen().bridge() : null;
        }
        return kit.memory.bridges().stream()
                .min(Comparator.comparingDouble(b -> here.distance(b.entryNear(here)) + b.length()))
                .orElse(null);
    }

    /** The point {@link #BEYOND} past {@code end}, coming from {@code start} along the bridge. */
    private static Point2 past(Point2 start, Point2 end) {
        double length = start.distance(end);
        return new Point2(end.x() + (end.x() - start.x()) / length * BEYOND,
                end.z() + (end.z() - start.z()) / length * BEYOND);
    }

    private RiverMap.Side sideOf(Point2 p) {
        return kit.grounder.side(p);
    }
}
