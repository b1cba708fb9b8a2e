package io.orchard.agents.map;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.function.BiConsumer;

/**
 * Where the castle may stand. The agent perceives the castle only as the compass sector it lies in
 * (as the paper has it, "rather vaguely"), so the estimate keeps a grid of candidate centres and
 * strikes out those that contradict what the agent learns: each sector seen from a new place,
 * every place known to be outside the castle (where the agent stood, where trees, tables and
 * fruit are, the river), and a move refused because it entered the castle.
 *
 * <p>What the world guarantees and the estimate uses: the castle is a keep at least
 * 14 by 10 units with a tower on each corner, so it covers a disc of radius
 * {@value #CORE_RADIUS} around its centre and reaches at most {@value #MAX_RADIUS} from it; it
 * keeps 12 units from the river and 10 from the world's edge.
 *
 * <p>Not thread-safe.
 */
public final class CastleEstimate {

    /** The castle covers at least a disc of this radius around its centre. */
    public static final double CORE_RADIUS = 5;

    /** No part of the castle lies farther than this from its centre. */
    public static final double MAX_RADIUS = 16.5;

    /** The castle keeps at least this far from the river. */
    public static final double WATER_CLEARANCE = 12;

    private static final double SPACING = 2;
    private static final double SLACK = SPACING * 0.75;
    private static final double LOCATED_SPREAD = 8;

    private final double x0;
    private final double z0;
    private final int nx;
    private final int nz;
    private final boolean[] alive;
    private int aliveCount;
    private long version;
    private Point2 lastPlace;
    private Sector lastSector;
    private Point2 centre;
    private double spread;
    private boolean bounded;
    private final List<Contact> contacts = new ArrayList<>();

    /**
     * A refused move: the castle comes within {@code radius} of the path from {@code from} to {@code to}.
     *
     * @param from   where the move started
     * @param to     where it should have ended
     * @param radius the radius of the agent refused
     */
    public record Contact(Point2 from, Point2 to, double radius) {}

    /** A fresh estimate: the castle may be anywhere at least 15 units inside the bounds. */
    public CastleEstimate(Bounds bounds) {
        double inset = 10 + CORE_RADIUS;
        x0 = bounds.minX() + inset;
        z0 = bounds.minZ() + inset;
        nx = Math.max(1, (int) Math.floor((bounds.width() - 2 * inset) / SPACING) + 1);
        nz = Math.max(1, (int) Math.floor((bounds.depth() - 2 * inset) / SPACING) + 1);
        alive = new boolean[nx * nz];
        Arrays.fill(alive, true);
        aliveCount = alive.length;
    }

    /** The castle lies in {@code sector} seen from {@code place}. */
    public void observe(Point2 place, Sector sector) {
        if (sector.equals(lastSector) && lastPlace != null && lastPlace.distance(place) < 2) {
            return;
        }
        lastPlace = place;
        lastSector = sector;
        boolean[] before = alive.clone();
        int beforeCount = aliveCount;
        double sectorCentre = sector.ordinal() * 45.0;
        for (int i = 0; i < alive.length; i++) {
            if (alive[i] && !inSector(place, sectorCentre, cx(i), cz(i))) {
                kill(i);
            }
        }
        if (aliveCount == 0) {
            // What was learnt before contradicts this sighting: trust the sighting.
            for (int i = 0; i < alive.length; i++) {
                alive[i] = inSector(place, sectorCentre, cx(i), cz(i));
                aliveCount += alive[i] ? 1 : 0;
            }
        }
        if (aliveCount != beforeCount || !Arrays.equals(before, alive)) {
            changed();
        }
    }

    /** No castle centre lies within {@code clearance} of {@code point}: the point is outside the castle by that much. */
    public void exclude(Point2 point, double clearance) {
        double reach = clearance - SLACK;
        if (reach <= 0) {
            return;
        }
        int[] killed = new int[64];
        int count = 0;
        int i0 = Math.max(0, (int) Math.floor((point.x() - reach - x0) / SPACING));
        int i1 = Math.min(nx - 1, (int) Math.ceil((point.x() + reach - x0) / SPACING));
        int k0 = Math.max(0, (int) Math.floor((point.z() - reach - z0) / SPACING));
        int k1 = Math.min(nz - 1, (int) Math.ceil((point.z() + reach - z0) / SPACING));
        for (int k = k0; k <= k1; k++) {
            for (int i = i0; i <= i1; i++) {
                int index = k * nx + i;
                if (alive[index] && Math.hypot(cx(index) - point.x(), cz(index) - point.z()) < reach) {
                    if (count == killed.length) {
                        killed = java.util.Arrays.copyOf(killed, count * 2);
                    }
                    killed[count++] = index;
                }
            }
        }
        if (count == 0 || count == aliveCount) {
            return; // nothing new, or a contradiction: keep the estimate rather than lose it
        }
        for (int j = 0; j < count; j++) {
            kill(killed[j]);
        }
        changed();
    }

    /**
     * A move of an agent of {@code radius} from {@code from} to {@code to} was refused because it
     * entered the castle: the castle comes within {@code radius} of that path.
     */
    public void touched(Point2 from, Point2 to, double radius) {
        contacts.add(new Contact(from, to, radius));
        double reach = MAX_RADIUS + radius + SLACK;
        int before = aliveCount;
        for (int i = 0; i < alive.length; i++) {
            if (alive[i] && Circle.segmentDistance(from.x(), from.z(), to.x(), to.z(), cx(i), cz(i)) > reach) {
                kill(i);
            }
        }
        if (aliveCount == 0) {
            for (int i = 0; i < alive.length; i++) {
                double d = Circle.segmentDistance(from.x(), from.z(), to.x(), to.z(), cx(i), cz(i));
                alive[i] = d <= reach && d >= CORE_RADIUS + radius - SLACK;
                aliveCount += alive[i] ? 1 : 0;
            }
        }
        if (aliveCount != before || !bounded) {
            bounded = true;
            changed();
        }
    }

    /**
     * Whether the castle is known to be near a place the agent walked: a move was refused because
     * it entered the castle, so every candidate left lies within reach of that move.
     */
    public boolean bounded() {
        return bounded;
    }

    /** The moves the castle refused, oldest first. */
    public List<Contact> contacts() {
        return Collections.unmodifiableList(contacts);
    }

    /** Calls {@code action} with each candidate centre left. */
    public void forEachCandidate(BiConsumer<Double, Double> action) {
        for (int i = 0; i < alive.length; i++) {
            if (alive[i]) {
                action.accept(cx(i), cz(i));
            }
        }
    }

    /** The mean of the candidate centres left; empty when none is left. */
    public Optional<Point2> centre() {
        summarise();
        return Optional.ofNullable(centre);
    }

    /** How far the candidate centres left lie from their mean, at most. */
    public double spread() {
        summarise();
        return spread;
    }

    /** Whether the castle is located well enough to steer around: its candidates lie close together. */
    public boolean located() {
        summarise();
        return centre != null && spread <= LOCATED_SPREAD;
    }

    /** How many candidate centres are left. */
    public int candidates() {
        return aliveCount;
    }

    /** Grows by one each time the estimate changes. */
    public long version() {
        return version;
    }

    private boolean inSector(Point2 place, double sectorCentre, double x, double z) {
        double dx = x - place.x();
        double dz = z - place.z();
        double distance = Math.hypot(dx, dz);
        if (distance < 1e-9) {
            return true;
        }
        double compass = Math.toDegrees(Math.atan2(dx, -dz));
        double off = Math.abs(Math.IEEEremainder(compass - sectorCentre, 360));
        double tolerance = 22.5 + Math.toDegrees(Math.asin(Math.min(1, SLACK / distance))) + 0.5;
        return off <= tolerance;
    }

    private void kill(int i) {
        alive[i] = false;
        aliveCount--;
    }

    private void changed() {
        version++;
        centre = null;
        spread = -1;
    }

    private void summarise() {
        if (spread >= 0 || aliveCount == 0) {
            if (aliveCount == 0) {
                centre = null;
                spread = Double.MAX_VALUE;
            }
            return;
        }
        double sx = 0;
        double sz = 0;
        for (int i = 0; i < alive.length; i++) {
            if (alive[i]) {
                sx += cx(i);
                sz += cz(i);
            }
        }
        centre = new Point2(sx / aliveCount, sz / aliveCount);
        double far = 0;
        for (int i = 0; i < alive.length; i++) {
            if (alive[i]) {
                far = Math.max(far, Math.hypot(cx(i) - centre.x(), cz(i) - centre.z()));
            }
        }
        spread = far;
    }

    private double cx(int i) {
        return x0 + (i % nx) * SPACING;
    }

    private double cz(int i) {
        return z0 + (i / nx) * SPACING;
    }
}
