package io.orchard.agents.behaviour;

import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.KnownBridge;
import io.orchard.agents.map.KnownObstacle;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Purely reactive steering: from this tick's perception alone (no map), a short step as close to
 * the wanted direction as is free. Trunks, tables and agents in view are kept clear of; the river
 * in view is a wall along its nearest bank, except on a bridge's deck in view; the world's edge is
 * known from the bounds. Headings the agent was recently refused (say, by the castle, which it
 * cannot see) can be avoided for a while.
 */
public final class Steering {

    /** The room kept from what is in view. */
    public static final double MARGIN = 0.2;

    private final double radius;
    private final Bounds bounds;
    private final List<double[]> avoid = new ArrayList<>();

    /** Steering for a body of {@code radius} in a world of {@code bounds}. */
    public Steering(double radius, Bounds bounds) {
        this.radius = radius;
        this.bounds = bounds;
    }

    /** Avoids headings within {@code spread} radians of {@code heading} until simulated time {@code until}. */
    public void avoid(double heading, double spread, double until) {
        avoid.add(new double[] {heading, spread, until});
    }

    /**
     * The end of a free step of at most {@code length} units as close as possible to heading
     * {@code wanted}; empty when every direction is closed.
     *
     * @param time simulated time now, for the headings to avoid
     */
    public Optional<Point2> step(PerceptionMessage perception, @Nullable LandmarkPerceptionMessage landmarks,
                                 double wanted, double length, double time) {
        avoid.removeIf(a -> a[2] <= time);
        Point2 here = perception.position().onGround();
        double heading = perception.heading();
        List<double[]> circles = new ArrayList<>();
        for (PerceivedObject object : perception.objects()) {
            Point2 at = Bearings.toWorld(here, heading, object.at());
            circles.add(new double[] {at.x(), at.z(), KnownObstacle.blockRadius(object.kind(), object.radius())});
        }
        for (PerceivedAgent agent : perception.agents()) {
            Point2 at = Bearings.toWorld(here, heading, agent.at());
            circles.add(new double[] {at.x(), at.z(), agent.radius() + 0.2});
        }
        List<KnownBridge> decks = new ArrayList<>();
        Point2 shore = null;
        if (landmarks != null) {
            for (PerceivedBridge bridge : landmarks.bridges()) {
                decks.add(new KnownBridge(bridge.id(), Bearings.toWorld(here, heading, bridge.entryA()),
                        Bearings.toWorld(here, heading, bridge.entryB()), bridge.width()));
            }
            if (landmarks.river() != null) {
                shore = Bearings.toWorld(here, heading, landmarks.river().nearest());
            }
        }
        for (double scale : new double[] {1, 0.5}) {
            for (int k = 0; k <= 24; k++) {
                double turn = (k % 2 == 1 ? 1 : -1) * ((k + 1) / 2) * Math.toRadians(15);
                double direction = wanted + turn;
                if (avoided(direction)) {
                    continue;
                }
                Point2 end = Bearings.ahead(here, direction, length * scale);
                if (free(here, end, circles, shore, decks)) {
                    return Optional.of(end);
                }
            }
        }
        return Optional.empty();
    }

    private boolean avoided(double direction) {
        for (double[] a : avoid) {
            if (Math.abs(Bearings.normalise(direction - a[0])) < a[1]) {
                return true;
            }
        }
        return false;
    }

    private boolean free(Point2 here, Point2 end, List<double[]> circles, @Nullable Point2 shore,
                         List<KnownBridge> decks) {
        if (end.x() < bounds.minX() + radius + 0.1 || end.x() > bounds.maxX() - radius - 0.1
                || end.z() < bounds.minZ() + radius + 0.1 || end.z() > bounds.maxZ() - radius - 0.1) {
            return false;
        }
        for (double[] c : circles) {
            double reach = c[2] + radius + MARGIN;
            double now = Math.hypot(here.x() - c[0], here.z() - c[1]);
            double d = TerrainGrid.segmentDistance(here, end, c[0], c[1]);
            if (d < reach && (now >= reach || d < now - 1e-6)) {
                return false;
            }
        }
        boolean onDeck = onDeck(here, decks, 2.5);
        Point2 middle = new Point2((here.x() + end.x()) / 2, (here.z() + end.z()) / 2);
        if (onDeck && (shore == null || here.distance(shore) < 0.3)) {
            // On the deck the river's nearest point is the agent itself: stay on the deck or step off its ends.
            return onDeck(end, decks, 2.5) && onDeck(middle, decks, 2.5);
        }
        if (shore != null) {
            double nx = shore.x() - here.x();
            double nz = shore.z() - here.z();
            double length = Math.hypot(nx, nz);
            if (length > 1e-6) {
                nx /= length;
                nz /= length;
                for (Point2 p : new Point2[] {middle, end}) {
                    double into = (p.x() - shore.x()) * nx + (p.z() - shore.z()) * nz;
                    if (into > -(radius + 0.4) && !onDeck(p, decks, 1.5)) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    private boolean onDeck(Point2 p, List<KnownBridge> decks, double beyond) {
        for (KnownBridge deck : decks) {
            if (deck.covers(p, radius + 0.15, beyond)) {
                return true;
            }
        }
        return false;
    }
}
