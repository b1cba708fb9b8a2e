package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonFormat;

/**
 * A bridge in a lean perception, written as the array
 * {@code [id, distanceA, bearingA, distanceB, bearingB, width]}: a {@link PerceivedBridge} in
 * centimetres and milliradians.
 *
 * @param id        {@code B1} or {@code B2}
 * @param distanceA ground distance to the entry on the agent's bank, in centimetres
 * @param bearingA  angle to that entry from the agent's heading, in milliradians, -3141 to 3142
 * @param distanceB ground distance to the entry on the far bank, in centimetres
 * @param bearingB  angle to that entry from the agent's heading, in milliradians, -3141 to 3142
 * @param width     width of the deck, in centimetres, at least 1
 */
@JsonFormat(shape = JsonFormat.Shape.ARRAY)
public record LeanBridge(String id, int distanceA, int bearingA, int distanceB, int bearingB, int width) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LeanBridge {
        Checks.id(id, "id");
        LeanUnits.distance(distanceA, "distanceA");
        LeanUnits.bearing(bearingA, "bearingA");
        LeanUnits.distance(distanceB, "distanceB");
        LeanUnits.bearing(bearingB, "bearingB");
        LeanUnits.size(width, "width");
    }

    /** The bridge as the ordinary perception gives it. */
    public static LeanBridge of(PerceivedBridge bridge) {
        return new LeanBridge(bridge.id(), LeanUnits.centimetres(bridge.entryA().distance()),
                (int) LeanUnits.milliradians(bridge.entryA().bearing()), LeanUnits.centimetres(bridge.entryB().distance()),
                (int) LeanUnits.milliradians(bridge.entryB().bearing()), LeanUnits.size(bridge.width()));
    }

    /** The bridge in units and radians, as the ordinary perception gives it. */
    public PerceivedBridge toPerceived() {
        return new PerceivedBridge(id, LeanUnits.relative(distanceA, bearingA), LeanUnits.relative(distanceB, bearingB),
                LeanUnits.units(width));
    }
}
