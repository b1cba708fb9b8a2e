package io.orchard.protocol.value;

/**
 * A tree or a table of the world, as its bounding cylinder.
 *
 * @param id       the object's id ({@code T1}, {@code T2}... for trees, {@code D1}... for tables)
 * @param kind     tree or table
 * @param position the centre of the cylinder on the ground
 * @param radius   the cylinder's radius (a tree's crown; a table's top)
 * @param height   the cylinder's height (a tree's top; a table's top surface)
 */
public record Obstacle(String id, ObjectKind kind, Point2 position, double radius, double height) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Obstacle {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        Checks.present(position, "position");
        Checks.positive(radius, "radius");
        Checks.positive(height, "height");
    }
}
