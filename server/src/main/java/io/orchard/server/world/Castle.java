package io.orchard.server.world;

import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.Point2;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;

/**
 * The castle: as in the paper, the projection of its walls onto the ground, extruded to their
 * height. Agents cannot enter it and cannot see through it; perception gives only the compass
 * sector it lies in.
 *
 * <p>Immutable; the polygon is prepared once for movement and line-of-sight questions.
 */
public final class Castle {

    private final CastleShape shape;
    private final Polygon polygon;
    private final PreparedGeometry prepared;
    private final Region region;
    private final Point2 centre;

    /** @param shape a footprint already known to be a valid polygon */
    Castle(CastleShape shape) {
        this.shape = shape;
        this.polygon = Shapes.polygon(shape.footprint());
        this.prepared = PreparedGeometryFactory.prepare(polygon);
        this.region = new Region(polygon);
        Coordinate c = polygon.getCentroid().getCoordinate();
        this.centre = new Point2(c.x, c.y);
    }

    /** The castle as scenario files and viewers describe it. */
    public CastleShape shape() {
        return shape;
    }

    /** The outline of the walls on the ground. */
    public List<Point2> footprint() {
        return shape.footprint();
    }

    /** The height of the walls. */
    public double height() {
        return shape.height();
    }

    /** The centre of the footprint's area: where the castle is, for its compass sector. */
    public Point2 centre() {
        return centre;
    }

    Polygon polygon() {
        return polygon;
    }

    PreparedGeometry prepared() {
        return prepared;
    }

    Region region() {
        return region;
    }
}
