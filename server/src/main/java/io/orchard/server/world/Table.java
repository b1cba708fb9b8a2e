package io.orchard.server.world;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;

/**
 * A table, as in the paper a bounding cylinder. The whole cylinder blocks movement (an agent does
 * not walk under a table); fruit may lie on its top, at the table's height.
 *
 * @param id       the table's id, {@code D1}, {@code D2}... (for "desk", since T is taken by trees)
 * @param position the centre of the table on the ground
 * @param radius   the radius of the top
 * @param height   the height of the top surface
 */
public record Table(String id, Point2 position, double radius, double height) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Table {
        Checks.id(id, "id");
        Checks.present(position, "position");
        Checks.positive(radius, "radius");
        Checks.positive(height, "height");
    }

    /** The table a table obstacle describes. */
    public static Table of(Obstacle obstacle) {
        if (obstacle.kind() != ObjectKind.TABLE) {
            throw new IllegalArgumentException(obstacle.id() + " is a " + obstacle.kind().wireName() + ", not a table");
        }
        return new Table(obstacle.id(), obstacle.position(), obstacle.radius(), obstacle.height());
    }

    /** This table as the protocol describes it. */
    public Obstacle obstacle() {
        return new Obstacle(id, ObjectKind.TABLE, position, radius, height);
    }
}
