package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.List;

/**
 * The river as far as the agent has seen it: a band of water across the world, built from
 * sightings of its nearest bank (and from the bridges, which span it at right angles).
 *
 * <p>The model: the sightings fix the direction in which the river mostly runs; along that
 * direction each bank is a line through the bank points seen, interpolated between them and
 * continued {@value #EXTRAPOLATION} units beyond the last one along the river's direction there.
 * Where only one bank has been seen, the other lies {@link #width()} beyond it. Where neither has
 * been seen the river is unknown and {@link #water} answers false: the agent walks on, sees the
 * river as it comes near, and the band grows.
 *
 * <p>Not thread-safe.
 */
public final class RiverMap {

    /** The width assumed until both banks have been seen: generated rivers are 8 to 11 wide. */
    public static final double DEFAULT_WIDTH = 10;

    /** How far beyond its last sighting a bank is continued. */
    public static final double EXTRAPOLATION = 25;

    private static final double SAME_POINT = 1.0;
    private static final double MAX_SLOPE = 3;

    /** Which side of the river a point lies on. */
    public enum Side {
        /** On the bank with the lower cross-river coordinate. */
        LOW,
        /** In the water. */
        WATER,
        /** On the bank with the higher cross-river coordinate. */
        HIGH,
        /** Nowhere the river is known near. */
        UNKNOWN
    }

    private final List<ShoreSighting> sightings = new ArrayList<>();
    private long version;
    private Band band;

    /**
     * Takes a sighting of the bank. Sightings of nearly the same point are merged, keeping the
     * nearer observer's.
     *
     * @return whether the model changed
     */
    public boolean sighted(ShoreSighting sighting) {
        if (sighting.distance() < 0.3) {
            return false; // standing on a bridge: the "nearest point" is the agent itself
        }
        for (int i = 0; i < sightings.size(); i++) {
            ShoreSighting old = sightings.get(i);
            if (old.shore().distance(sighting.shore()) < SAME_POINT && sameSide(old, sighting)) {
                if (sighting.distance() < old.distance() - 0.5) {
                    sightings.set(i, sighting);
                    changed();
                    return true;
                }
                return false;
            }
        }
        sightings.add(sighting);
        changed();
        return true;
    }

    /** Takes what a bridge tells: the river flows across the segment between its entries. */
    public void bridged(KnownBridge bridge) {
        Point2 a = bridge.entryA();
        Point2 b = bridge.entryB();
        double length = bridge.length();
        if (length < 3) {
            return;
        }
        double ux = (b.x() - a.x()) / length;
        double uz = (b.z() - a.z()) / length;
        double across = Bearings.headingOf(-uz, ux);
        sighted(new ShoreSighting(a, new Point2(a.x() + ux, a.z() + uz), across));
        sighted(new ShoreSighting(b, new Point2(b.x() - ux, b.z() - uz), across));
    }

    /** Every sighting kept, oldest first. */
    public List<ShoreSighting> sightings() {
        return Collections.unmodifiableList(sightings);
    }

    /** Whether the river has been seen at all. */
    public boolean seen() {
        return !sightings.isEmpty();
    }

    /** Grows by one each time the model changes. */
    public long version() {
        return version;
    }

    /** The width of the band: measured where both banks were seen, else {@link #DEFAULT_WIDTH}. */
    public double width() {
        return band().width;
    }

    /**
     * Whether a point is in the water as far as the model knows, or within {@code margin} of it.
     * Bridges are not taken into account: their decks cover the water.
     */
    public boolean water(double x, double z, double margin) {
        return side(x, z, margin) == Side.WATER;
    }

    /** The side of the river a point lies on; WATER within {@code margin} of the water too. */
    public Side side(double x, double z, double margin) {
        Band b = band();
        if (b.low.isEmpty() && b.high.isEmpty()) {
            return Side.UNKNOWN;
        }
        double s = x * b.tx + z * b.tz;
        double q = x * b.ux + z * b.uz;
        double lo = shore(b.low, s);
        double hi = shore(b.high, s);
        if (Double.isNaN(lo) && Double.isNaN(hi)) {
            return Side.UNKNOWN;
        }
        if (Double.isNaN(lo)) {
            lo = hi - b.width;
        }
        if (Double.isNaN(hi)) {
            hi = lo + b.width;
        }
        if (q <= lo - margin) {
            return Side.LOW;
        }
        if (q >= hi + margin) {
            return Side.HIGH;
        }
        return Side.WATER;
    }

    private void changed() {
        version++;
        band = null;
    }

    private static boolean sameSide(ShoreSighting a, ShoreSighting b) {
        double ax = a.shore().x() - a.from().x();
        double az = a.shore().z() - a.from().z();
        double bx = b.shore().x() - b.from().x();
        double bz = b.shore().z() - b.from().z();
        return ax * bx + az * bz > 0;
    }

    private Band band() {
        if (band == null) {
            band = new Band(sightings);
        }
        return band;
    }

    /** A bank point in the river's frame: along, across, and the bank's slope there. */
    private record Sample(double s, double q, double slope) {}

    private static double shore(List<Sample> samples, double s) {
        if (samples.isEmpty()) {
            return Double.NaN;
        }
        Sample first = samples.get(0);
        Sample last = samples.get(samples.size() - 1);
        if (s < first.s - EXTRAPOLATION || s > last.s + EXTRAPOLATION) {
            return Double.NaN;
        }
        if (s <= first.s) {
            return first.q + first.slope * (s - first.s);
        }
        if (s >= last.s) {
            return last.q + last.slope * (s - last.s);
        }
        int lo = 0;
        int hi = samples.size() - 1;
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (samples.get(mid).s <= s) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Sample a = samples.get(lo);
        Sample b = samples.get(hi);
        double f = b.s == a.s ? 0 : (s - a.s) / (b.s - a.s);
        return a.q + f * (b.q - a.q);
    }

    /** The band in a frame along the river's mean direction (t) and across it (u). */
    private static final class Band {
        final double tx;
        final double tz;
        final double ux;
        final double uz;
        final List<Sample> low = new ArrayList<>();
        final List<Sample> high = new ArrayList<>();
        final double width;

        Band(List<ShoreSighting> sightings) {
            double sin = 0;
            double cos = 0;
            for (ShoreSighting s : sightings) {
                sin += Math.sin(2 * s.riverHeading());
                cos += Math.cos(2 * s.riverHeading());
            }
            double frame = sightings.isEmpty() ? 0 : Math.atan2(sin, cos) / 2;
            tx = -Math.sin(frame);
            tz = -Math.cos(frame);
            ux = -tz;
            uz = tx;
            for (ShoreSighting sighting : sightings) {
                Point2 p = sighting.shore();
                double s = p.x() * tx + p.z() * tz;
                double q = p.x() * ux + p.z() * uz;
                double slope = -Math.tan(halfTurn(sighting.riverHeading() - frame));
                slope = Math.max(-MAX_SLOPE, Math.min(MAX_SLOPE, slope));
                double towardsWater = (p.x() - sighting.from().x()) * ux + (p.z() - sighting.from().z()) * uz;
                (towardsWater > 0 ? low : high).add(new Sample(s, q, slope));
            }
            low.sort(Comparator.comparingDouble(Sample::s));
            high.sort(Comparator.comparingDouble(Sample::s));
            width = measuredWidth();
        }

        /** An angle reduced to (-pi/2, pi/2]: a river runs both ways. */
        private static double halfTurn(double angle) {
            double a = Math.IEEEremainder(angle, Math.PI);
            return a <= -Math.PI / 2 ? a + Math.PI : a;
        }

        private double measuredWidth() {
            if (low.isEmpty() || high.isEmpty()) {
                return DEFAULT_WIDTH;
            }
            List<Double> widths = new ArrayList<>();
            for (Sample sample : low) {
                if (sample.s >= high.get(0).s && sample.s <= high.get(high.size() - 1).s) {
                    widths.add(shore(high, sample.s) - sample.q);
                }
            }
            if (widths.isEmpty()) {
                return DEFAULT_WIDTH;
            }
            Collections.sort(widths);
            return Math.max(6, Math.min(14, widths.get(widths.size() / 2)));
        }
    }
}
