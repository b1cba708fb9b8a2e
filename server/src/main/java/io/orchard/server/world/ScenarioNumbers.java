package io.orchard.server.world;

import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.scenario.Scenario;
import java.util.ArrayList;
import java.util.List;

/**
 * Checks that every number of a scenario lies in a range the geometry can work with, before any of
 * it is built: a world of ±1e308 overflows its own width to infinity and fails deep in JTS, and a
 * world of ±1e6 would make a grid of billions of cells. Each problem names the field by its path in
 * the file ({@code bounds.maxX}, {@code trees[2].radius}) and the object it belongs to.
 */
final class ScenarioNumbers {

    /** The farthest any coordinate may lie from the origin, in units: a world at most 20 km across. */
    static final double MAX_COORDINATE = 10_000;

    /** The largest radius, height or width of a thing, in units. */
    static final double MAX_SIZE = 1_000;

    private final List<String> problems = new ArrayList<>();

    private ScenarioNumbers() {}

    /** Every number of the scenario that is out of range, in the order of the file; empty when none is. */
    static List<String> problems(Scenario scenario) {
        ScenarioNumbers check = new ScenarioNumbers();
        check.coordinate("bounds.minX", "the bounds", scenario.bounds().minX());
        check.coordinate("bounds.minZ", "the bounds", scenario.bounds().minZ());
        check.coordinate("bounds.maxX", "the bounds", scenario.bounds().maxX());
        check.coordinate("bounds.maxZ", "the bounds", scenario.bounds().maxZ());
        check.points("castle.footprint", "the castle", scenario.castle().footprint());
        check.size("castle.height", "the castle", scenario.castle().height());
        check.points("river.outline", "the river", scenario.river().outline());
        for (int i = 0; i < scenario.bridges().size(); i++) {
            BridgeShape bridge = scenario.bridges().get(i);
            String at = "bridges[" + i + "]";
            String what = "bridge " + bridge.id();
            check.point(at + ".entryA", what, bridge.entryA());
            check.point(at + ".entryB", what, bridge.entryB());
            check.size(at + ".width", what, bridge.width());
        }
        check.obstacles("trees", "tree", scenario.trees());
        check.obstacles("tables", "table", scenario.tables());
        for (int i = 0; i < scenario.fruit().size(); i++) {
            FruitState fruit = scenario.fruit().get(i);
            String at = "fruit[" + i + "].position";
            String what = "fruit " + fruit.id();
            check.coordinate(at + ".x", what, fruit.position().x());
            check.coordinate(at + ".y", what, fruit.position().y());
            check.coordinate(at + ".z", what, fruit.position().z());
        }
        return check.problems;
    }

    private void obstacles(String list, String kind, List<Obstacle> obstacles) {
        for (int i = 0; i < obstacles.size(); i++) {
            Obstacle obstacle = obstacles.get(i);
            String at = list + "[" + i + "]";
            String what = kind + " " + obstacle.id();
            point(at + ".position", what, obstacle.position());
            size(at + ".radius", what, obstacle.radius());
            size(at + ".height", what, obstacle.height());
        }
    }

    private void points(String field, String what, List<Point2> points) {
        for (int i = 0; i < points.size(); i++) {
            point(field + "[" + i + "]", what, points.get(i));
        }
    }

    private void point(String field, String what, Point2 point) {
        coordinate(field + ".x", what, point.x());
        coordinate(field + ".z", what, point.z());
    }

    private void coordinate(String field, String what, double value) {
        if (!(Math.abs(value) <= MAX_COORDINATE)) {
            problems.add(what + ": " + field + " must lie between " + Plane.format(-MAX_COORDINATE) + " and "
                    + Plane.format(MAX_COORDINATE) + ", was " + value);
        }
    }

    private void size(String field, String what, double value) {
        if (!(value <= MAX_SIZE)) {
            problems.add(what + ": " + field + " must be at most " + Plane.format(MAX_SIZE) + ", was " + value);
        }
    }
}
