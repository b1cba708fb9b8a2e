package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.CastleShape;
import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.geom.PrecisionModel;
import org.locationtech.jts.precision.GeometryPrecisionReducer;

/**
 * Lays out the castle of a generated world: a rectangular keep with a square tower on each corner
 * (so its outline is not convex and it hides what is behind it from some angles but not others),
 * turned at a random angle, at least {@link #WATER_CLEARANCE} units from the river and the bridges.
 */
final class CastleLayout {

    /** The least distance between the castle's walls and the river or a bridge. */
    static final double WATER_CLEARANCE = 12;

    /** The least distance between the castle's walls and the world's edge. */
    static final double EDGE_CLEARANCE = 10;

    private static final PrecisionModel MILLIMETRES = new PrecisionModel(1000);

    private final RandomGenerator random;
    private final Bounds bounds;

    CastleLayout(RandomGenerator random, Bounds bounds) {
        this.random = random;
        this.bounds = bounds;
    }

    /** @param avoid the river and the bridges' decks */
    CastleShape make(List<Region> avoid) {
        double keepX = uniform(7, 10);
        double keepZ = uniform(5, 8);
        double tower = uniform(1.5, 2.5);
        double height = RiverLayout.round(uniform(8, 12));
        Geometry shape = Shapes.rectangle(-keepX, -keepZ, keepX, keepZ);
        for (int corner = 0; corner < 4; corner++) {
            double cx = (corner % 2 == 0 ? -1 : 1) * keepX;
            double cz = (corner < 2 ? -1 : 1) * keepZ;
            shape = shape.union(Shapes.rectangle(cx - tower, cz - tower, cx + tower, cz + tower));
        }
        Coordinate[] local = ((Polygon) shape).getExteriorRing().getCoordinates();
        for (int attempt = 0; attempt < 500; attempt++) {
            double turn = uniform(0, Math.PI / 2);
            double x = uniform(bounds.minX(), bounds.maxX());
            double z = uniform(bounds.minZ(), bounds.maxZ());
            Polygon castle = place(local, turn, x, z);
            if (fits(castle, avoid)) {
                return new CastleShape(Shapes.outline(castle), height);
            }
        }
        throw new IllegalStateException("could not find room for the castle in the world " + bounds);
    }

    private static Polygon place(Coordinate[] local, double turn, double x, double z) {
        double cos = StrictMath.cos(turn);
        double sin = StrictMath.sin(turn);
        List<Coordinate> ring = new ArrayList<>(local.length);
        for (Coordinate c : local) {
            ring.add(new Coordinate(x + c.x * cos - c.y * sin, z + c.x * sin + c.y * cos));
        }
        Polygon placed = Shapes.FACTORY.createPolygon(ring.toArray(Coordinate[]::new));
        return (Polygon) GeometryPrecisionReducer.reduce(placed, MILLIMETRES);
    }

    private boolean fits(Polygon castle, List<Region> avoid) {
        if (!Shapes.rectangle(bounds.minX() + EDGE_CLEARANCE, bounds.minZ() + EDGE_CLEARANCE,
                bounds.maxX() - EDGE_CLEARANCE, bounds.maxZ() - EDGE_CLEARANCE).covers(castle)) {
            return false;
        }
        for (Region region : avoid) {
            if (region.geometry().isWithinDistance(castle, WATER_CLEARANCE)) {
                return false;
            }
        }
        return true;
    }

    private double uniform(double from, double to) {
        return from + (to - from) * random.nextDouble();
    }
}
