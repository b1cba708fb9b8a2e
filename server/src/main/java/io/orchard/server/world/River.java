package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.locationtech.jts.algorithm.locate.IndexedPointInAreaLocator;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.LineSegment;
import org.locationtech.jts.geom.Location;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.index.strtree.ItemBoundable;
import org.locationtech.jts.index.strtree.STRtree;
import org.locationtech.jts.operation.distance.IndexedFacetDistance;

/**
 * The river: a band of water across the whole world that divides the land into two banks. Agents
 * cross it only on a bridge.
 *
 * <p>Its outline is split in two kinds of edge: the shore, where water meets land, and the stretches
 * that lie on the world's edge, where the river leaves the world. Only the shore counts when asking
 * where the nearest water is and which way the river runs.
 *
 * <p>Immutable; the polygon, the shore and the two banks are indexed once. Whether the river is
 * beyond an agent's sight is answered from a coarse grid of lower bounds on the distance to the
 * water, each cell worked out the first time it is asked about: most agents are far from the river,
 * and the nearest-shore search it saves them was a sixth of a crowded tick.
 */
public final class River {

    private static final double MIN_LAND_AREA = 1e-6;
    private static final double FAR_CELL = 8;

    private final RiverShape shape;
    private final Polygon polygon;
    private final Region region;
    private final STRtree shore = new STRtree();
    private final int shoreSegments;
    private final List<Polygon> land;
    private final Map<Bank, IndexedPointInAreaLocator> banks = new EnumMap<>(Bank.class);
    private final IndexedFacetDistance outlineDistance;
    private final double farMinX;
    private final double farMinZ;
    private final int farColumns;
    private final int farRows;
    /** Per cell, a lower bound of the distance from any of its points to the water; NaN until asked. */
    private final float[] farBound;

    /** @param shape an outline already known to be a valid polygon */
    River(RiverShape shape, Bounds bounds) {
        this.shape = shape;
        this.polygon = Shapes.polygon(shape.outline());
        this.region = new Region(polygon);
        Coordinate[] ring = polygon.getExteriorRing().getCoordinates();
        int count = 0;
        for (int i = 0; i + 1 < ring.length; i++) {
            if (!onWorldEdge(ring[i], ring[i + 1], bounds)) {
                shore.insert(new Envelope(ring[i], ring[i + 1]), new LineSegment(ring[i], ring[i + 1]));
                count++;
            }
        }
        this.shoreSegments = count;
        shore.build();
        this.land = landPieces(Shapes.rectangle(bounds).difference(polygon));
        if (land.size() == 2) {
            nameBanks(land.get(0), land.get(1));
        }
        this.outlineDistance = new IndexedFacetDistance(polygon);
        this.farMinX = bounds.minX();
        this.farMinZ = bounds.minZ();
        this.farColumns = Math.max(1, (int) Math.ceil(bounds.width() / FAR_CELL));
        this.farRows = Math.max(1, (int) Math.ceil(bounds.depth() / FAR_CELL));
        this.farBound = new float[farColumns * farRows];
        java.util.Arrays.fill(farBound, Float.NaN);
    }

    private static boolean onWorldEdge(Coordinate a, Coordinate b, Bounds bounds) {
        return (near(a.x, bounds.minX()) && near(b.x, bounds.minX()))
                || (near(a.x, bounds.maxX()) && near(b.x, bounds.maxX()))
                || (near(a.y, bounds.minZ()) && near(b.y, bounds.minZ()))
                || (near(a.y, bounds.maxZ()) && near(b.y, bounds.maxZ()));
    }

    private static boolean near(double a, double b) {
        return Math.abs(a - b) <= 1e-7;
    }

    private static List<Polygon> landPieces(Geometry land) {
        List<Polygon> pieces = new ArrayList<>();
        for (int i = 0; i < land.getNumGeometries(); i++) {
            Geometry piece = land.getGeometryN(i);
            if (piece instanceof Polygon polygon && polygon.getArea() > MIN_LAND_AREA) {
                pieces.add(polygon);
            }
        }
        return List.copyOf(pieces);
    }

    private void nameBanks(Polygon first, Polygon second) {
        Coordinate a = first.getCentroid().getCoordinate();
        Coordinate b = second.getCentroid().getCoordinate();
        boolean northSouth = Math.abs(b.y - a.y) >= Math.abs(b.x - a.x);
        Bank firstName;
        Bank secondName;
        if (northSouth) {
            firstName = a.y < b.y ? Bank.NORTH : Bank.SOUTH;
            secondName = a.y < b.y ? Bank.SOUTH : Bank.NORTH;
        } else {
            firstName = a.x < b.x ? Bank.WEST : Bank.EAST;
            secondName = a.x < b.x ? Bank.EAST : Bank.WEST;
        }
        banks.put(firstName, locator(first));
        banks.put(secondName, locator(second));
    }

    private static IndexedPointInAreaLocator locator(Polygon piece) {
        IndexedPointInAreaLocator locator = new IndexedPointInAreaLocator(piece);
        locator.locate(piece.getCoordinate()); // builds its index now
        return locator;
    }

    /** The river as scenario files and viewers describe it. */
    public RiverShape shape() {
        return shape;
    }

    /** The outline of the water on the ground. */
    public List<Point2> outline() {
        return shape.outline();
    }

    /** The names of the two banks, for example north and south. */
    public Set<Bank> banks() {
        return Collections.unmodifiableSet(banks.keySet());
    }

    /** Whether a ground point lies in the river (on its shore included), whether or not a bridge is over it. */
    public boolean contains(Point2 point) {
        return region.contains(point.x(), point.z());
    }

    Polygon polygon() {
        return polygon;
    }

    Region region() {
        return region;
    }

    /** How many pieces of land the river leaves within the world; a valid river leaves two. */
    int landPieceCount() {
        return land.size();
    }

    /** The bank a point lies on; empty in the river and outside the world. */
    Optional<Bank> bankOf(double x, double z) {
        if (region.contains(x, z)) {
            return Optional.empty();
        }
        Coordinate at = new Coordinate(x, z);
        for (Map.Entry<Bank, IndexedPointInAreaLocator> bank : banks.entrySet()) {
            if (bank.getValue().locate(at) != Location.EXTERIOR) {
                return Optional.of(bank.getKey());
            }
        }
        return Optional.empty();
    }

    /**
     * Whether every point of the river lies farther than {@code range} from (x, z). Cheap and never
     * wrong when it says yes; it may say no for a river just beyond the range, and says no outside
     * the world.
     */
    boolean beyond(double x, double z, double range) {
        int column = (int) Math.floor((x - farMinX) / FAR_CELL);
        int row = (int) Math.floor((z - farMinZ) / FAR_CELL);
        if (column < 0 || row < 0 || column >= farColumns || row >= farRows) {
            return false;
        }
        int cell = row * farColumns + column;
        float bound = farBound[cell];
        if (Float.isNaN(bound)) {
            bound = farBound(column, row);
            // Another thread may work out the same cell at once; both write the same value.
            farBound[cell] = bound;
        }
        return bound > range;
    }

    private float farBound(int column, int row) {
        double centreX = farMinX + (column + 0.5) * FAR_CELL;
        double centreZ = farMinZ + (row + 0.5) * FAR_CELL;
        if (region.contains(centreX, centreZ)) {
            return 0;
        }
        // Any point of the cell is at most half a diagonal from its centre; a point in the water is
        // at least as far from the centre as the outline is. The millimetre absorbs float rounding.
        double outline = outlineDistance.distance(Shapes.FACTORY.createPoint(new Coordinate(centreX, centreZ)));
        return (float) Math.max(0, outline - FAR_CELL * Math.sqrt(0.5) - 1e-3);
    }

    /** The nearest point of the river to (x, z), and its direction there. */
    RiverPoint nearest(double x, double z) {
        Coordinate at = new Coordinate(x, z);
        LineSegment segment = nearestShore(at);
        boolean inside = region.contains(x, z);
        Coordinate nearest = inside ? at : segment.closestPoint(at);
        double distance = inside ? 0 : nearest.distance(at);
        double heading = Plane.normalize(Plane.heading(segment.p1.x - segment.p0.x, segment.p1.y - segment.p0.y));
        if (heading > Math.PI / 2) {
            heading -= Math.PI;
        } else if (heading <= -Math.PI / 2) {
            heading += Math.PI;
        }
        return new RiverPoint(new Point2(nearest.x, nearest.y), distance, heading);
    }

    private LineSegment nearestShore(Coordinate at) {
        if (shoreSegments == 0) {
            throw new IllegalStateException("the river has no shore inside the world");
        }
        return (LineSegment) shore.nearestNeighbour(new Envelope(at), at, River::shoreDistance);
    }

    private static double shoreDistance(ItemBoundable one, ItemBoundable other) {
        Object first = one.getItem();
        Object second = other.getItem();
        LineSegment segment = (LineSegment) (first instanceof LineSegment ? first : second);
        Coordinate point = (Coordinate) (first instanceof LineSegment ? second : first);
        return segment.distance(point);
    }
}
