package io.orchard.protocol.value;

/**
 * A fruit of the world as viewers see it.
 *
 * @param id       the fruit's id
 * @param kind     tomato, banana or coconut
 * @param position the centre of its sphere
 * @param support  the id of the table it lies on or the tree it hangs in; absent on the ground
 */
public record FruitState(String id, FruitKind kind, Vec3 position, @Nullable String support) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public FruitState {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        Checks.present(position, "position");
        if (support != null) {
            Checks.id(support, "support");
        }
    }
}
