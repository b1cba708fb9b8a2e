package io.orchard.protocol.value;

/**
 * A fruit in an agent's perception. Unlike other objects, fruit is given by its absolute position
 * (as in the paper), because an agent must know exactly whether it is within grasping distance.
 *
 * @param id       the fruit's id, to name it in a grasp request
 * @param kind     tomato, banana or coconut
 * @param position the centre of the fruit's sphere in world coordinates
 * @param radius   the sphere's radius
 * @param support  the id of the table it lies on or the tree it hangs in; absent when it lies on
 *                 the ground
 */
public record PerceivedFruit(String id, FruitKind kind, Vec3 position, double radius, @Nullable String support) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceivedFruit {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        Checks.present(position, "position");
        Checks.positive(radius, "radius");
        if (support != null) {
            Checks.id(support, "support");
        }
    }
}
