package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;

/**
 * A bridge, as the paper gives it: two entry points on the two banks and the width of its deck.
 * The deck is the rectangle of that width centred on the segment between the entries.
 *
 * @param id     {@code B1} or {@code B2}
 * @param entryA one entry
 * @param entryB the other entry
 * @param width  the deck's width
 */
public record KnownBridge(String id, Point2 entryA, Point2 entryB, double width) {

    /** The distance between the entries. */
    public double length() {
        return entryA.distance(entryB);
    }

    /** The middle of the deck. */
    public Point2 middle() {
        return new Point2((entryA.x() + entryB.x()) / 2, (entryA.z() + entryB.z()) / 2);
    }

    /** The entry nearer to {@code p}. */
    public Point2 entryNear(Point2 p) {
        return p.distance(entryA) <= p.distance(entryB) ? entryA : entryB;
    }

    /** The entry farther from {@code p}. */
    public Point2 entryFar(Point2 p) {
        return p.distance(entryA) <= p.distance(entryB) ? entryB : entryA;
    }

    /**
     * Whether the point lies on the deck shrunk by {@code inset} on its long sides and lengthened by
     * {@code beyond} past each entry.
     */
    public boolean covers(Point2 p, double inset, double beyond) {
        double length = length();
        double ux = (entryB.x() - entryA.x()) / length;
        double uz = (entryB.z() - entryA.z()) / length;
        double dx = p.x() - entryA.x();
        double dz = p.z() - entryA.z();
        double along = dx * ux + dz * uz;
        double across = -dx * uz + dz * ux;
        return along >= -beyond && along <= length + beyond && Math.abs(across) <= width / 2 - inset;
    }
}
