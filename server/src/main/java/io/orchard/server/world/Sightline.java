package io.orchard.server.world;

import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;

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

    Sightline(Castle castle) {
        this.castle = castle;
        this.envelope = castle.polygon().getEnvelopeInternal();
    }

    /** Whether the castle comes within {@code range} of a point (by its bounding box): if not, it hides nothing there. */
    boolean near(double x, double z, double range) {
        return envelope.intersects(new Envelope(x - range, x + range, z - range, z + range));
    }

    boolean clear(double ax, double az, double bx, double bz) {
        if (!envelope.intersects(new Envelope(ax, bx, az, bz))) {
            return true;
        }
        Geometry line = Shapes.path(ax, az, bx, bz);
        if (!castle.prepared().intersects(line)) {
            return true;
        }
        return !castle.polygon().relate(line, INTERIORS_MEET);
    }
}
