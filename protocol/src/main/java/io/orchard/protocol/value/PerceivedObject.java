package io.orchard.protocol.value;

/**
 * A tree or a table in an agent's perception, by its position relative to the agent.
 *
 * @param id     the object's id, stable for the whole game (for example {@code T17})
 * @param kind   tree or table
 * @param at     where it is relative to the agent
 * @param radius radius of its bounding cylinder
 * @param height height of the cylinder (a table's top; a tree's crown)
 */
public record PerceivedObject(String id, ObjectKind kind, RelativePosition at, double radius, double height) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceivedObject {
        Checks.id(id, "id");
        Checks.present(kind, "kind");
        Checks.present(at, "at");
        Checks.positive(radius, "radius");
        Checks.positive(height, "height");
    }
}
