package io.orchard.server.world.scenario;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.RiverShape;
import java.util.List;

/**
 * A world written down: what a scenario file holds, in the protocol's value records, in the order
 * the file lists it. Every field is required. A scenario that exists is well-formed; whether its
 * things fit together is checked by {@code World.fromScenario}.
 *
 * @param format  the version of the file format, {@link #FORMAT}
 * @param bounds  the rectangle agents may walk on
 * @param castle  the castle
 * @param river   the river, crossing the whole world
 * @param bridges the bridges over the river, at least one
 * @param trees   the trees, each of kind {@code tree}; the radius is the crown's
 * @param tables  the tables, each of kind {@code table}
 * @param fruit   the fruit, on the ground, on tables or in trees
 */
public record Scenario(int format,
                       Bounds bounds,
                       CastleShape castle,
                       RiverShape river,
                       List<BridgeShape> bridges,
                       List<Obstacle> trees,
                       List<Obstacle> tables,
                       List<FruitState> fruit) {

    /** The format this server reads and writes. */
    public static final int FORMAT = 1;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Scenario {
        if (format != FORMAT) {
            throw new ScenarioException("scenario format " + format + " is not supported: this server reads format "
                    + FORMAT);
        }
        Checks.present(bounds, "bounds");
        Checks.present(castle, "castle");
        Checks.present(river, "river");
        bridges = Checks.list(bridges, "bridges");
        trees = Checks.list(trees, "trees");
        tables = Checks.list(tables, "tables");
        fruit = Checks.list(fruit, "fruit");
    }
}
