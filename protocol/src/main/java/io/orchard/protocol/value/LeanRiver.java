package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonFormat;

/**
 * The river in a lean perception, written as the array {@code [distance, bearing, across]}: a
 * {@link PerceivedRiver} in centimetres and milliradians.
 *
 * @param distance ground distance to the nearest visible point of its bank, in centimetres
 * @param bearing  angle to that point from the agent's heading, in milliradians, -3141 to 3142
 * @param across   the direction the river runs, relative to the agent's heading, in milliradians
 */
@JsonFormat(shape = JsonFormat.Shape.ARRAY)
public record LeanRiver(int distance, int bearing, int across) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LeanRiver {
        LeanUnits.distance(distance, "distance");
        LeanUnits.bearing(bearing, "bearing");
    }

    /** The river as the ordinary perception gives it. */
    public static LeanRiver of(PerceivedRiver river) {
        return new LeanRiver(LeanUnits.centimetres(river.nearest().distance()),
                (int) LeanUnits.milliradians(river.nearest().bearing()), (int) LeanUnits.milliradians(river.across()));
    }

    /** The river in units and radians, as the ordinary perception gives it. */
    public PerceivedRiver toPerceived() {
        return new PerceivedRiver(LeanUnits.relative(distance, bearing), LeanUnits.radians(across));
    }
}
