package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonFormat;

/**
 * A point in world coordinates in whole centimetres, written as the array {@code [x, y, z]}: the
 * perceiving agent's own position in a lean perception.
 *
 * @param x east (+) / west (-), in centimetres
 * @param y height above the ground, in centimetres
 * @param z south (+) / north (-), in centimetres
 */
@JsonFormat(shape = JsonFormat.Shape.ARRAY)
public record LeanPoint(int x, int y, int z) {

    /** The point, rounded to centimetres. */
    public static LeanPoint of(Vec3 point) {
        return new LeanPoint(LeanUnits.centimetres(point.x()), LeanUnits.centimetres(point.y()),
                LeanUnits.centimetres(point.z()));
    }

    /** The point in units. */
    public Vec3 toVec3() {
        return new Vec3(LeanUnits.units(x), LeanUnits.units(y), LeanUnits.units(z));
    }
}
