package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Polygon;

/**
 * Checks that the things of a well-formed scenario fit together, and makes the world if they do.
 * Every rule is listed, with its message, in {@code docs/scenarios.md}.
 *
 * <p>Three stages: first that every number lies in a range the geometry can work with
 * ({@link ScenarioNumbers}); then what the geometry needs (unique ids, things in the right list,
 * outlines that are valid polygons); then, on the world built from them, where things are (inside the world, not
 * overlapping, the river crossing the world with bridges that span it, fruit where fruit can be).
 * Every problem of a stage is collected, so that an author fixes a file in one round.
 */
final class ScenarioCheck {

    private final Scenario scenario;
    private final List<String> problems = new ArrayList<>();

    private ScenarioCheck(Scenario scenario) {
        this.scenario = scenario;
    }

    static World build(Scenario scenario) {
        if (scenario == null) {
            throw new ScenarioException("no scenario given");
        }
        ScenarioCheck check = new ScenarioCheck(scenario);
        check.problems.addAll(ScenarioNumbers.problems(scenario));
        check.throwIfAny();
        check.ids();
        check.lists();
        check.outlines();
        check.throwIfAny();
        World world = new World(scenario.bounds(),
                scenario.trees().stream().map(Tree::of).toList(),
                scenario.tables().stream().map(Table::of).toList(),
                new Castle(scenario.castle()),
                new River(scenario.river(), scenario.bounds()),
                scenario.bridges().stream().map(Bridge::new).toList(),
                scenario.fruit().stream().map(Fruit::of).toList());
        check.insideWorld(world);
        check.riverAndBridges(world);
        check.overlaps(world);
        check.problems.addAll(new FruitCheck(world, scenario.fruit()).problems());
        check.throwIfAny();
        return world;
    }

    private void throwIfAny() {
        if (!problems.isEmpty()) {
            throw new ScenarioException(problems);
        }
    }

    // ---- stage 1 --------------------------------------------------------------------------------

    private void ids() {
        Map<String, String> seen = new HashMap<>();
        for (BridgeShape bridge : scenario.bridges()) {
            claim(seen, bridge.id(), "bridge " + bridge.id());
        }
        for (Obstacle tree : scenario.trees()) {
            claim(seen, tree.id(), tree.kind().wireName() + " " + tree.id());
        }
        for (Obstacle table : scenario.tables()) {
            claim(seen, table.id(), table.kind().wireName() + " " + table.id());
        }
        for (FruitState fruit : scenario.fruit()) {
            claim(seen, fruit.id(), "fruit " + fruit.id());
        }
    }

    private void claim(Map<String, String> seen, String id, String what) {
        String before = seen.putIfAbsent(id, what);
        if (before != null) {
            problems.add("duplicate id " + id + ": " + before + " and " + what);
        }
    }

    private void lists() {
        for (Obstacle tree : scenario.trees()) {
            if (tree.kind() != ObjectKind.TREE) {
                problems.add(tree.kind().wireName() + " " + tree.id() + " is listed among the trees");
            }
        }
        for (Obstacle table : scenario.tables()) {
            if (table.kind() != ObjectKind.TABLE) {
                problems.add(table.kind().wireName() + " " + table.id() + " is listed among the tables");
            }
        }
    }

    private void outlines() {
        Shapes.invalidity(Shapes.polygon(scenario.castle().footprint()))
                .ifPresent(why -> problems.add("the castle's footprint is not a valid polygon: " + why));
        Shapes.invalidity(Shapes.polygon(scenario.river().outline()))
                .ifPresent(why -> problems.add("the river's outline is not a valid polygon: " + why));
    }

    // ---- stage 2 --------------------------------------------------------------------------------

    private void insideWorld(World world) {
        Bounds bounds = world.bounds();
        Obstacles obstacles = world.obstacleIndex();
        for (int i = 0; i < obstacles.size(); i++) {
            double r = obstacles.blockRadius[i];
            if (!inside(bounds, obstacles.x[i], obstacles.z[i], r)) {
                problems.add(obstacles.describe(i) + " lies outside the world " + describe(bounds));
            }
        }
        Polygon area = Shapes.rectangle(bounds);
        if (!area.covers(world.castle().polygon())) {
            problems.add("the castle lies outside the world " + describe(bounds));
        }
        if (!area.covers(world.river().polygon())) {
            problems.add("the river reaches outside the world " + describe(bounds)
                    + ": its outline must end on the world's edges");
        }
        for (Bridge bridge : world.bridges()) {
            if (!area.covers(bridge.polygon())) {
                problems.add("bridge " + bridge.id() + " reaches outside the world " + describe(bounds));
            }
        }
        for (FruitState fruit : scenario.fruit()) {
            if (!bounds.contains(fruit.position().x(), fruit.position().z())) {
                problems.add("fruit " + fruit.id() + " lies outside the world " + describe(bounds));
            }
        }
    }

    private static boolean inside(Bounds bounds, double x, double z, double r) {
        return x - r >= bounds.minX() - Plane.EPSILON && x + r <= bounds.maxX() + Plane.EPSILON
                && z - r >= bounds.minZ() - Plane.EPSILON && z + r <= bounds.maxZ() + Plane.EPSILON;
    }

    private static String describe(Bounds bounds) {
        return "(x " + Plane.format(bounds.minX()) + " to " + Plane.format(bounds.maxX()) + ", z "
                + Plane.format(bounds.minZ()) + " to " + Plane.format(bounds.maxZ()) + ")";
    }

    private void riverAndBridges(World world) {
        River river = world.river();
        int pieces = river.landPieceCount();
        if (pieces != 2) {
            problems.add("the river does not cross the world: it must divide the land into two banks, but leaves "
                    + pieces + (pieces == 1 ? " piece" : " pieces"));
        }
        if (world.bridges().isEmpty()) {
            problems.add("the river has no bridge: agents could never cross it");
        }
        for (Bridge bridge : world.bridges()) {
            String name = "bridge " + bridge.id();
            boolean aWet = river.contains(bridge.entryA());
            boolean bWet = river.contains(bridge.entryB());
            if (aWet || bWet) {
                Point2 wet = aWet ? bridge.entryA() : bridge.entryB();
                problems.add(name + " does not span the river: entry " + (aWet ? "A " : "B ")
                        + Plane.format(wet.x(), wet.z()) + " is in the river");
                continue;
            }
            if (pieces != 2) {
                continue;
            }
            Optional<Bank> a = river.bankOf(bridge.entryA().x(), bridge.entryA().z());
            Optional<Bank> b = river.bankOf(bridge.entryB().x(), bridge.entryB().z());
            if (a.isPresent() && a.equals(b)) {
                problems.add(name + " does not span the river: both entries are on the " + a.get().label());
            }
        }
    }

    private void overlaps(World world) {
        Obstacles obstacles = world.obstacleIndex();
        Castle castle = world.castle();
        River river = world.river();
        for (int i = 0; i < obstacles.size(); i++) {
            int first = i;
            double x = obstacles.x[i];
            double z = obstacles.z[i];
            double r = obstacles.blockRadius[i];
            double margin = r + obstacles.maxBlockRadius;
            List<Integer> hits = new ArrayList<>();
            obstacles.grid.forEachInBox(x - margin, z - margin, x + margin, z + margin, j -> {
                if (j > first) {
                    double limit = r + obstacles.blockRadius[j] - Plane.EPSILON;
                    double dx = obstacles.x[j] - x;
                    double dz = obstacles.z[j] - z;
                    if (dx * dx + dz * dz < limit * limit) {
                        hits.add(j);
                    }
                }
            });
            hits.sort(Comparator.naturalOrder());
            for (int j : hits) {
                problems.add(obstacles.describe(i) + " overlaps " + obstacles.describe(j));
            }
            if (castle.region().touchedBy(x, z, x, z, r)) {
                problems.add(obstacles.describe(i) + " overlaps the castle");
            }
            if (river.region().touchedBy(x, z, x, z, r)) {
                problems.add(obstacles.describe(i) + " overlaps the river");
            }
            for (Bridge bridge : world.bridges()) {
                if (touches(bridge, x, z, r)) {
                    problems.add(obstacles.describe(i) + " overlaps bridge " + bridge.id());
                }
            }
        }
        String interiorsMeet = "T********";
        if (castle.polygon().relate(river.polygon(), interiorsMeet)) {
            problems.add("the castle overlaps the river");
        }
        List<Bridge> bridges = world.bridges();
        for (int i = 0; i < bridges.size(); i++) {
            if (castle.polygon().relate(bridges.get(i).polygon(), interiorsMeet)) {
                problems.add("the castle overlaps bridge " + bridges.get(i).id());
            }
            for (int j = i + 1; j < bridges.size(); j++) {
                if (bridges.get(i).polygon().relate(bridges.get(j).polygon(), interiorsMeet)) {
                    problems.add("bridge " + bridges.get(i).id() + " overlaps bridge " + bridges.get(j).id());
                }
            }
        }
    }

    private static boolean touches(Bridge bridge, double x, double z, double r) {
        Envelope box = new Envelope(x - r, x + r, z - r, z + r);
        if (!box.intersects(bridge.polygon().getEnvelopeInternal())) {
            return false;
        }
        return bridge.covers(x, z) || bridge.polygon().distance(Shapes.point(x, z)) < r - Plane.EPSILON;
    }
}
