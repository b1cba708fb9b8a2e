package io.orchard.server.world;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Vec3;

/**
 * A fruit: a sphere of its kind's radius at a known position, lying on the ground, lying on a
 * table or hanging in a tree.
 *
 * @param id       the fruit's id, {@code F1}, {@code F2}...
 * @param kind     tomato, banana or coconut, which fixes radius and points
 * @param position the centre of the sphere; on the ground its height is its radius
 * @param support  the id of the table it lies on or the tree it hangs in; null on the ground
 */
public record Fruit(String id, FruitKind kind, Vec3 position, @Nullable String support) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Fruit {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        Checks.present(position, "position");
        if (support != null) {
            Checks.id(support, "support");
        }
    }

    /** The fruit a fruit state describes. */
    public static Fruit of(FruitState state) {
        return new Fruit(state.id(), state.kind(), state.position(), state.support());
    }

    /** The radius of the sphere. */
    public double radius() {
        return kind.radius();
    }

    /** Whether it lies on the ground rather than on a table or in a tree. */
    public boolean onGround() {
        return support == null;
    }

    /** This fruit as the protocol describes it. */
    public FruitState state() {
        return new FruitState(id, kind, position, support);
    }
}
