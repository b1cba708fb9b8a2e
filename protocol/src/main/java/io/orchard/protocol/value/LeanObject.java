package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonFormat;

/**
 * A tree or a table in a lean perception, written as the array
 * {@code [id, kind, distance, bearing, radius, height]}: a {@link PerceivedObject} in centimetres
 * and milliradians.
 *
 * @param id       stable for the whole game ({@code T17}, {@code D2})
 * @param kind     tree or table
 * @param distance ground distance between centres, in centimetres, 0 or more
 * @param bearing  angle from the agent's heading, in milliradians, -3141 to 3142 (3142 is π)
 * @param radius   radius of its cylinder, in centimetres, at least 1
 * @param height   height of its cylinder, in centimetres, at least 1
 */
@JsonFormat(shape = JsonFormat.Shape.ARRAY)
public record LeanObject(String id, ObjectKind kind, int distance, int bearing, int radius, int height) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LeanObject {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        LeanUnits.distance(distance, "distance");
        LeanUnits.bearing(bearing, "bearing");
        LeanUnits.size(radius, "radius");
        LeanUnits.size(height, "height");
    }

    /** The object as the ordinary perception gives it. */
    public static LeanObject of(PerceivedObject object) {
        return new LeanObject(object.id(), object.kind(), LeanUnits.centimetres(object.at().distance()),
                (int) LeanUnits.milliradians(object.at().bearing()), LeanUnits.size(object.radius()),
                LeanUnits.size(object.height()));
    }

    /** The object in units and radians, as the ordinary perception gives it. */
    public PerceivedObject toPerceived() {
        return new PerceivedObject(id, kind, LeanUnits.relative(distance, bearing), LeanUnits.units(radius),
                LeanUnits.units(height));
    }
}
