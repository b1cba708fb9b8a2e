package io.orchard.server.world;

import java.util.List;
import org.locationtech.jts.algorithm.Distance;
import org.locationtech.jts.algorithm.locate.IndexedPointInAreaLocator;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.LineSegment;
import org.locationtech.jts.geom.Location;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * An area that agents must not enter (the castle, the water of the river), prepared once for the
 * question asked on every move: does a disc of radius r, swept along a segment, touch it?
 *
 * <p>A swept disc touches the area exactly when its start lies inside, or some edge of the area
 * lies closer than r to the segment: a segment that enters the area crosses an edge, which is then
 * at distance 0. So the answer needs only a point-in-area test and the edges near the segment,
 * found through an STRtree; no geometry is built per question.
 *
 * <p>Both indexes are built in the constructor, so queries do not change the object.
 */
final class Region {

    private final Geometry area;
    private final Envelope envelope;
    private final IndexedPointInAreaLocator locator;
    private final STRtree edges = new STRtree();

    /** @param area a polygon or a multi-polygon; may be empty (then nothing is ever touched) */
    Region(Geometry area) {
        this.area = area;
        this.envelope = area.getEnvelopeInternal();
        this.locator = new IndexedPointInAreaLocator(area);
        for (int i = 0; i < area.getNumGeometries(); i++) {
            Polygon polygon = (Polygon) area.getGeometryN(i);
            addRing(polygon.getExteriorRing().getCoordinates());
            for (int h = 0; h < polygon.getNumInteriorRing(); h++) {
                addRing(polygon.getInteriorRingN(h).getCoordinates());
            }
        }
        edges.build();
        locator.locate(new Coordinate(envelope.getMinX(), envelope.getMinY())); // builds its index now
    }

    private void addRing(Coordinate[] ring) {
        for (int i = 0; i + 1 < ring.length; i++) {
            LineSegment edge = new LineSegment(ring[i], ring[i + 1]);
            Envelope box = new Envelope(ring[i], ring[i + 1]);
            edges.insert(box, edge);
        }
    }

    Geometry geometry() {
        return area;
    }

    boolean isEmpty() {
        return area.isEmpty();
    }

    /** Whether the point lies inside the area or on its edge. */
    boolean contains(double x, double z) {
        return !area.isEmpty() && envelope.covers(x, z) && locator.locate(new Coordinate(x, z)) != Location.EXTERIOR;
    }

    /** Whether a disc of the radius, swept from a to b, overlaps the area (merely touching does not count). */
    boolean touchedBy(double ax, double az, double bx, double bz, double radius) {
        if (area.isEmpty()) {
            return false;
        }
        Envelope reach = new Envelope(ax, bx, az, bz);
        reach.expandBy(radius);
        if (!reach.intersects(envelope)) {
            return false;
        }
        if (locator.locate(new Coordinate(ax, az)) == Location.INTERIOR) {
            return true;
        }
        Coordinate a = new Coordinate(ax, az);
        Coordinate b = new Coordinate(bx, bz);
        double limit = radius - Plane.EPSILON;
        @SuppressWarnings("unchecked")
        List<LineSegment> near = edges.query(reach);
        for (LineSegment edge : near) {
            double distance = a.equals2D(b)
                    ? Distance.pointToSegment(a, edge.p0, edge.p1)
                    : Distance.segmentToSegment(a, b, edge.p0, edge.p1);
            if (distance < limit) {
                return true;
            }
        }
        return false;
    }

    /**
     * The fraction of the way from a to b the disc travels before it first touches the area, found
     * by bisection to within 1/1024 of the path and rounded down; call only when
     * {@link #touchedBy} is true.
     */
    double firstContact(double ax, double az, double bx, double bz, double radius) {
        if (touchedBy(ax, az, ax, az, radius)) {
            return 0;
        }
        double free = 0;
        double blocked = 1;
        while (blocked - free > 1.0 / 1024) {
            double middle = (free + blocked) / 2;
            if (touchedBy(ax, az, ax + (bx - ax) * middle, az + (bz - az) * middle, radius)) {
                blocked = middle;
            } else {
                free = middle;
            }
        }
        return free;
    }
}
