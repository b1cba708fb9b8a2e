package io.orchard.agents.map;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Vec3;

/**
 * A fruit the agent has seen and that is not known to be gone.
 *
 * @param id       the fruit's id, to name in a grasp
 * @param kind     tomato, banana or coconut
 * @param position the centre of its sphere, world coordinates
 * @param radius   the sphere's radius
 * @param support  the table it lies on or the tree it hangs in; null on the ground
 * @param seenTick the last tick it was seen in
 */
public record KnownFruit(String id, FruitKind kind, Vec3 position, double radius, @Nullable String support,
                         long seenTick) {

    /** Where it is on the ground (its x and z). */
    public Point2 ground() {
        return position.onGround();
    }

    /** The height of its centre. */
    public double height() {
        return position.y();
    }

    /** Whether it lies on the ground rather than on a table or in a tree. */
    public boolean onGround() {
        return support == null;
    }

    /** Its points: 1 for a tomato, 2 for a banana, 3 for a coconut. */
    public int points() {
        return kind.points();
    }
}
