package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.geom.PrecisionModel;
import org.locationtech.jts.precision.GeometryPrecisionReducer;

/**
 * Lays out the river and its two bridges for a generated world. The river is a band of constant
 * width around a gently bending centre line (a long sine wave) that runs at a random angle, mostly
 * east-west or mostly north-south, and is cut off at the world's edges. The bridges cross it at
 * right angles, about a third and two thirds of the way along, and reach {@link #OVERHANG} units
 * onto each bank.
 */
final class RiverLayout {

    /** How far a bridge's entries lie beyond the river's banks. */
    static final double OVERHANG = 2;

    private static final PrecisionModel MILLIMETRES = new PrecisionModel(1000);

    /** What was laid out. */
    record Layout(RiverShape river, List<BridgeShape> bridges) {}

    private final RandomGenerator random;
    private final Bounds bounds;
    private final double size;

    RiverLayout(RandomGenerator random, Bounds bounds) {
        this.random = random;
        this.bounds = bounds;
        this.size = Math.min(bounds.width(), bounds.depth());
    }

    Layout make() {
        for (int attempt = 0; attempt < 100; attempt++) {
            Layout layout = attempt();
            if (layout != null) {
                return layout;
            }
        }
        throw new IllegalStateException("could not lay out a river across the world " + bounds);
    }

    private Layout attempt() {
        double angle = (random.nextBoolean() ? 0 : Math.PI / 2) + Math.toRadians(uniform(-25, 25));
        double ux = StrictMath.cos(angle);
        double uz = StrictMath.sin(angle);
        double nx = -uz;
        double nz = ux;
        double centreX = (bounds.minX() + bounds.maxX()) / 2;
        double centreZ = (bounds.minZ() + bounds.maxZ()) / 2;
        double offset = uniform(-size / 8, size / 8);
        double width = uniform(8, 11);
        double amplitude = size * uniform(0.02, 0.04);
        double wavelength = size * uniform(0.6, 1.0);
        double phase = uniform(0, 2 * Math.PI);
        double half = 0.75 * Math.hypot(bounds.width(), bounds.depth());
        double step = size / 40;

        List<double[]> line = new ArrayList<>(); // x, z, unit normal x, unit normal z
        for (double s = -half; s <= half + 1e-9; s += step) {
            double wave = amplitude * StrictMath.sin(2 * Math.PI * s / wavelength + phase);
            double slope = amplitude * 2 * Math.PI / wavelength * StrictMath.cos(2 * Math.PI * s / wavelength + phase);
            double x = centreX + nx * offset + ux * s + nx * wave;
            double z = centreZ + nz * offset + uz * s + nz * wave;
            double tx = ux + nx * slope;
            double tz = uz + nz * slope;
            double length = Math.hypot(tx, tz);
            line.add(new double[] {x, z, -tz / length, tx / length});
        }
        List<Coordinate> ring = new ArrayList<>();
        for (double[] p : line) {
            ring.add(new Coordinate(p[0] + p[2] * width / 2, p[1] + p[3] * width / 2));
        }
        for (int i = line.size() - 1; i >= 0; i--) {
            double[] p = line.get(i);
            ring.add(new Coordinate(p[0] - p[2] * width / 2, p[1] - p[3] * width / 2));
        }
        ring.add(new Coordinate(ring.get(0)));
        Polygon band = Shapes.FACTORY.createPolygon(ring.toArray(Coordinate[]::new));
        Geometry clipped = GeometryPrecisionReducer.reduce(band.intersection(Shapes.rectangle(bounds)), MILLIMETRES);
        if (!(clipped instanceof Polygon river) || !river.isValid() || river.getNumInteriorRing() > 0) {
            return null;
        }
        List<BridgeShape> bridges = bridges(line, width);
        return bridges == null ? null : new Layout(new RiverShape(Shapes.outline(river)), bridges);
    }

    /** Two bridges at about a third and two thirds of the river's course inside the world. */
    private List<BridgeShape> bridges(List<double[]> line, double width) {
        double margin = width / 2 + OVERHANG + 12;
        List<double[]> inside = new ArrayList<>();
        for (double[] p : line) {
            if (p[0] > bounds.minX() + margin && p[0] < bounds.maxX() - margin
                    && p[1] > bounds.minZ() + margin && p[1] < bounds.maxZ() - margin) {
                inside.add(p);
            }
        }
        if (inside.size() < 6) {
            return null;
        }
        double deck = round(uniform(3.5, 4.5));
        List<BridgeShape> bridges = new ArrayList<>();
        double[] shares = {uniform(0.25, 0.38), uniform(0.62, 0.75)};
        for (int b = 0; b < shares.length; b++) {
            double[] p = inside.get((int) Math.round(shares[b] * (inside.size() - 1)));
            double reach = width / 2 + OVERHANG;
            Point2 a = new Point2(round(p[0] + p[2] * reach), round(p[1] + p[3] * reach));
            Point2 other = new Point2(round(p[0] - p[2] * reach), round(p[1] - p[3] * reach));
            bridges.add(new BridgeShape("B" + (b + 1), a, other, deck));
        }
        return bridges;
    }

    private double uniform(double from, double to) {
        return from + (to - from) * random.nextDouble();
    }

    static double round(double value) {
        return Math.round(value * 1000) / 1000.0;
    }
}
