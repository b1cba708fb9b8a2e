package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.operation.valid.IsValidOp;
import org.locationtech.jts.operation.valid.TopologyValidationError;

/**
 * Conversions between the protocol's ground points and JTS geometry. JTS's x is the world's x and
 * JTS's y is the world's z; nothing else changes.
 */
final class Shapes {

    /** Floating precision: the world's coordinates are doubles and stay doubles. */
    static final GeometryFactory FACTORY = new GeometryFactory();

    private Shapes() {}

    static Coordinate coordinate(Point2 point) {
        return new Coordinate(point.x(), point.z());
    }

    static Point2 point2(Coordinate coordinate) {
        return new Point2(coordinate.x, coordinate.y);
    }

    static Point point(double x, double z) {
        return FACTORY.createPoint(new Coordinate(x, z));
    }

    static LineString segment(double ax, double az, double bx, double bz) {
        return FACTORY.createLineString(new Coordinate[] {new Coordinate(ax, az), new Coordinate(bx, bz)});
    }

    /** The segment a-b, or the point a when both ends are the same. */
    static Geometry path(double ax, double az, double bx, double bz) {
        return ax == bx && az == bz ? point(ax, az) : segment(ax, az, bx, bz);
    }

    /** A polygon from an outline given without the closing point (a closing point is tolerated). */
    static Polygon polygon(List<Point2> outline) {
        List<Coordinate> ring = new ArrayList<>(outline.size() + 1);
        for (Point2 point : outline) {
            ring.add(coordinate(point));
        }
        if (!ring.get(0).equals2D(ring.get(ring.size() - 1))) {
            ring.add(new Coordinate(ring.get(0)));
        }
        if (ring.size() < 4) {
            // Two distinct points repeated: JTS needs four coordinates; the validity check reports it.
            ring.add(1, new Coordinate(ring.get(0)));
        }
        return FACTORY.createPolygon(ring.toArray(Coordinate[]::new));
    }

    static Polygon rectangle(Bounds bounds) {
        return rectangle(bounds.minX(), bounds.minZ(), bounds.maxX(), bounds.maxZ());
    }

    static Polygon rectangle(double minX, double minZ, double maxX, double maxZ) {
        return FACTORY.createPolygon(new Coordinate[] {
            new Coordinate(minX, minZ), new Coordinate(maxX, minZ), new Coordinate(maxX, maxZ),
            new Coordinate(minX, maxZ), new Coordinate(minX, minZ)});
    }

    /** The exterior ring of a polygon as ground points, without the closing point. */
    static List<Point2> outline(Polygon polygon) {
        Coordinate[] ring = polygon.getExteriorRing().getCoordinates();
        List<Point2> points = new ArrayList<>(ring.length - 1);
        for (int i = 0; i < ring.length - 1; i++) {
            points.add(point2(ring[i]));
        }
        return List.copyOf(points);
    }

    /** Why a geometry is not a valid simple shape, or empty when it is valid. */
    static Optional<String> invalidity(Geometry geometry) {
        TopologyValidationError error = new IsValidOp(geometry).getValidationError();
        if (error == null) {
            return Optional.empty();
        }
        Coordinate at = error.getCoordinate();
        String where = at == null ? "" : " at " + Plane.format(at.x, at.y);
        return Optional.of(error.getMessage().toLowerCase(java.util.Locale.ROOT) + where);
    }
}
