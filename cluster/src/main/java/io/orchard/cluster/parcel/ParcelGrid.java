package io.orchard.cluster.parcel;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * The world's rectangle cut into squares of one side, counted from its north-west corner; the last
 * column and row may be narrower. A point belongs to the parcel whose square holds it (a point on a
 * border to the parcel east or south of it; a point beyond the world's edge to the nearest parcel).
 * Each parcel's halo reaches {@link #halo()} beyond its square.
 */
public final class ParcelGrid {

    private final Bounds bounds;
    private final double size;
    private final double halo;
    private final int columns;
    private final int rows;

    /**
     * Squares of side {@code size} over {@code bounds}, with halos {@code halo} wide.
     *
     * @throws IllegalArgumentException when the size or the halo is not a positive number
     */
    public ParcelGrid(Bounds bounds, double size, double halo) {
        if (!(size > 0) || Double.isInfinite(size)) {
            throw new IllegalArgumentException("parcel size must be a positive number of units, was " + size);
        }
        if (!(halo > 0) || Double.isInfinite(halo)) {
            throw new IllegalArgumentException("halo must be a positive number of units, was " + halo);
        }
        this.bounds = bounds;
        this.size = size;
        this.halo = halo;
        this.columns = Math.max(1, (int) Math.ceil(bounds.width() / size));
        this.rows = Math.max(1, (int) Math.ceil(bounds.depth() / size));
    }

    /** The side of a parcel. */
    public double size() {
        return size;
    }

    /** How far beyond its square a parcel's halo reaches. */
    public double halo() {
        return halo;
    }

    /** Every parcel, row by row from the north-west. */
    public List<ParcelId> all() {
        List<ParcelId> all = new ArrayList<>(columns * rows);
        for (int row = 0; row < rows; row++) {
            for (int column = 0; column < columns; column++) {
                all.add(new ParcelId(column, row));
            }
        }
        return all;
    }

    /** The parcel a point on the ground belongs to. */
    public ParcelId of(double x, double z) {
        return new ParcelId(clamp((int) Math.floor((x - bounds.minX()) / size), columns),
                clamp((int) Math.floor((z - bounds.minZ()) / size), rows));
    }

    /** The parcel a position belongs to. */
    public ParcelId of(Vec3 at) {
        return of(at.x(), at.z());
    }

    /** Whether a point lies in the parcel's halo: within {@link #halo()} of its square, or in it. */
    public boolean inHalo(ParcelId parcel, double x, double z) {
        return x >= minX(parcel) - halo && x <= maxX(parcel) + halo && z >= minZ(parcel) - halo
                && z <= maxZ(parcel) + halo;
    }

    /**
     * Whether a box lies wholly in the parcel's halo, away from its outer edge by {@code margin}:
     * then every agent that could be within the margin of the box is the parcel's or a ghost there.
     */
    public boolean holds(ParcelId parcel, double minX, double minZ, double maxX, double maxZ) {
        return minX >= minX(parcel) - halo && maxX <= maxX(parcel) + halo && minZ >= minZ(parcel) - halo
                && maxZ <= maxZ(parcel) + halo;
    }

    /** The parcels whose squares meet the box (grown by nothing), row by row. */
    public List<ParcelId> meeting(double minX, double minZ, double maxX, double maxZ) {
        ParcelId from = of(minX, minZ);
        ParcelId to = of(maxX, maxZ);
        List<ParcelId> met = new ArrayList<>();
        for (int row = from.row(); row <= to.row(); row++) {
            for (int column = from.column(); column <= to.column(); column++) {
                met.add(new ParcelId(column, row));
            }
        }
        return met;
    }

    /**
     * Whether a walker's path, with every agent it could touch on the way (within its radius and
     * {@code maxRadius} of the path), lies in the parcel's halo.
     */
    public boolean holds(ParcelId parcel, PathQuery path, double maxRadius) {
        double[] box = box(path, maxRadius);
        return holds(parcel, box[0], box[1], box[2], box[3]);
    }

    /** The parcels that own the agents a walker could touch on its path (within its radius and {@code maxRadius}). */
    public List<ParcelId> along(PathQuery path, double maxRadius) {
        double[] box = box(path, maxRadius);
        return meeting(box[0], box[1], box[2], box[3]);
    }

    private static double[] box(PathQuery path, double maxRadius) {
        double margin = path.radius() + maxRadius;
        return new double[] {Math.min(path.from().x(), path.to().x()) - margin,
                Math.min(path.from().z(), path.to().z()) - margin, Math.max(path.from().x(), path.to().x()) + margin,
                Math.max(path.from().z(), path.to().z()) + margin};
    }

    /** The parcels whose halos hold a point: those that keep a ghost of an agent standing there. */
    public List<ParcelId> seeing(double x, double z) {
        return meeting(x - halo, z - halo, x + halo, z + halo);
    }

    private double minX(ParcelId parcel) {
        return bounds.minX() + parcel.column() * size;
    }

    private double maxX(ParcelId parcel) {
        return parcel.column() == columns - 1 ? Math.max(bounds.maxX(), minX(parcel) + size) : minX(parcel) + size;
    }

    private double minZ(ParcelId parcel) {
        return bounds.minZ() + parcel.row() * size;
    }

    private double maxZ(ParcelId parcel) {
        return parcel.row() == rows - 1 ? Math.max(bounds.maxZ(), minZ(parcel) + size) : minZ(parcel) + size;
    }

    private static int clamp(int index, int count) {
        return Math.max(0, Math.min(count - 1, index));
    }
}
