package io.orchard.cluster.parcel;

/**
 * A parcel of the world: its column (west to east) and row (north to south), from 0.
 *
 * @param column the column, from the world's west edge
 * @param row    the row, from the world's north edge
 */
public record ParcelId(int column, int row) implements Comparable<ParcelId> {

    /** The parcel an entity id names: {@code "column,row"}, as {@link #toString()} writes it. */
    public static ParcelId parse(String id) {
        int comma = id.indexOf(',');
        if (comma < 0) {
            throw new IllegalArgumentException("a parcel is named column,row, was '" + id + "'");
        }
        return new ParcelId(Integer.parseInt(id.substring(0, comma)), Integer.parseInt(id.substring(comma + 1)));
    }

    @Override
    public int compareTo(ParcelId other) {
        return row != other.row ? Integer.compare(row, other.row) : Integer.compare(column, other.column);
    }

    @Override
    public String toString() {
        return column + "," + row;
    }
}
