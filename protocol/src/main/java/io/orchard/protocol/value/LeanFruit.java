package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonFormat;

/**
 * A fruit in a lean perception, written as the array {@code [id, kind, x, y, z, support]}: a
 * {@link PerceivedFruit} with its absolute position in centimetres. Its radius is its kind's
 * ({@link FruitKind#radius()}); {@code support} is {@code null} for a fruit on the ground.
 *
 * @param id      the fruit's id, to name in a grasp request
 * @param kind    tomato, banana or coconut
 * @param x       the centre of its sphere, east (+) / west (-), in centimetres
 * @param y       the centre's height above the ground, in centimetres
 * @param z       the centre, south (+) / north (-), in centimetres
 * @param support the table it lies on or the tree it hangs in; null on the ground
 */
@JsonFormat(shape = JsonFormat.Shape.ARRAY)
public record LeanFruit(String id, FruitKind kind, int x, int y, int z, @Nullable String support) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LeanFruit {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        if (support != null) {
            Checks.id(support, "support");
        }
    }

    /** The fruit as the ordinary perception gives it. */
    public static LeanFruit of(PerceivedFruit fruit) {
        return new LeanFruit(fruit.id(), fruit.kind(), LeanUnits.centimetres(fruit.position().x()),
                LeanUnits.centimetres(fruit.position().y()), LeanUnits.centimetres(fruit.position().z()),
                fruit.support());
    }

    /** The fruit in units, as the ordinary perception gives it, with its kind's radius. */
    public PerceivedFruit toPerceived() {
        return new PerceivedFruit(id, kind, new Vec3(LeanUnits.units(x), LeanUnits.units(y), LeanUnits.units(z)),
                kind.radius(), support);
    }
}
