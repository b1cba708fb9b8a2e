package io.orchard.server.world;

import org.locationtech.jts.algorithm.Orientation;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.Polygon;

/**
 * Line of sight on the ground: the castle's walls are the only thing tall and solid enough to hide
 * one point from another (trees and tables are seen past, as in the paper), and they hide whatever
 * lies behind them whatever its height.
 *
 * <p>A sight line is blocked when it passes through the inside of the castle; grazing a wall or a
 * corner does not block it.
 */
final class Sightline {

    private static final String INTERIORS_MEET = "T********";

    private final Castle castle;
    private final Envelope envelope;
    /** The castle's rings of walls: a wall from each point of a ring to the next. */
    private final Coordinate[][] rings;

    Sightline(Castle castle) {
        this.castle = castle;
        this.envelope = castle.polygon().getEnvelopeInternal();
        Polygon polygon = castle.polygon();
        this.rings = new Coordinate[polygon.getNumInteriorRing() + 1][];
        rings[0] = polygon.getExteriorRing().getCoordinates();
        for (int i = 0; i < polygon.getNumInteriorRing(); i++) {
            rings[i + 1] = polygon.getInteriorRingN(i).getCoordinates();
        }
    }

    /**
     * Whether the sight line crosses a wall properly: through the inside of both, away from the
     * wall's ends and its own. It then runs through the castle's inside on one side of the wall, so
     * it is blocked; the general test below (JTS's relate, which allocates a graph of the castle
     * for every line) is left for the lines that only touch walls or corners, or do not meet them
     * at all. The orientation tests are JTS's own exact ones, so both agree.
     */
    private boolean crossesAWall(double ax, double az, double bx, double bz) {
        Coordinate a = new Coordinate(ax, az);
        Coordinate b = new Coordinate(bx, bz);
        for (Coordinate[] ring : rings) {
            for (int i = 0; i + 1 < ring.length; i++) {
                Coordinate p = ring[i];
                Coordinate q = ring[i + 1];
                if (Orientation.index(a, b, p) * Orientation.index(a, b, q) < 0
                        && Orientation.index(p, q, a) * Orientation.index(p, q, b) < 0) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether the castle comes within {@code range} of a point (by its bounding box): if not, it hides nothing there. */
    boolean near(double x, double z, double range) {
        return envelope.intersects(new Envelope(x - range, x + range, z - range, z + range));
    }

    boolean clear(double ax, double az, double bx, double bz) {
        if (!envelope.intersects(new Envelope(ax, bx, az, bz))) {
            return true;
        }
        if (crossesAWall(ax, az, bx, bz)) {
            return false;
        }
        Geometry line = Shapes.path(ax, az, bx, bz);
        if (!castle.prepared().intersects(line)) {
            return true;
        }
        return !castle.polygon().relate(line, INTERIORS_MEET);
    }
}
