package io.orchard.server.world;

import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Point2;
import java.util.List;
import org.locationtech.jts.geom.Polygon;

/**
 * A bridge over the river, as in the paper its two entry points and its width. Its deck is the
 * rectangle of that width centred on the segment between the entries, with square ends at the
 * entries; agents may be over the river only where they are on a deck.
 *
 * <p>Immutable.
 */
public final class Bridge {

    private final BridgeShape shape;
    private final List<Point2> deck;
    private final Polygon polygon;
    private final double ux;
    private final double uz;
    private final double length;

    Bridge(BridgeShape shape) {
        this.shape = shape;
        Point2 a = shape.entryA();
        Point2 b = shape.entryB();
        this.length = a.distance(b);
        this.ux = (b.x() - a.x()) / length;
        this.uz = (b.z() - a.z()) / length;
        double half = shape.width() / 2;
        double nx = -uz * half;
        double nz = ux * half;
        this.deck = List.of(
                new Point2(a.x() + nx, a.z() + nz), new Point2(b.x() + nx, b.z() + nz),
                new Point2(b.x() - nx, b.z() - nz), new Point2(a.x() - nx, a.z() - nz));
        this.polygon = Shapes.polygon(deck);
    }

    /** The bridge as scenario files and viewers describe it. */
    public BridgeShape shape() {
        return shape;
    }

    /** The bridge's id, as scenario files and viewers name it. */
    public String id() {
        return shape.id();
    }

    /** Where the deck meets one bank. */
    public Point2 entryA() {
        return shape.entryA();
    }

    /** Where the deck meets the other bank. */
    public Point2 entryB() {
        return shape.entryB();
    }

    /** The deck's width, from railing to railing. */
    public double width() {
        return shape.width();
    }

    /** The four corners of the deck, in order around it. */
    public List<Point2> deck() {
        return deck;
    }

    /** Whether a ground point lies on the deck (its edges included). */
    public boolean covers(Point2 point) {
        return covers(point.x(), point.z());
    }

    boolean covers(double x, double z) {
        double dx = x - shape.entryA().x();
        double dz = z - shape.entryA().z();
        double along = dx * ux + dz * uz;
        double across = -dx * uz + dz * ux;
        return along >= -Plane.EPSILON && along <= length + Plane.EPSILON
                && Math.abs(across) <= shape.width() / 2 + Plane.EPSILON;
    }

    Polygon polygon() {
        return polygon;
    }
}
