package io.orchard.server.world;

import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * The scenario rules for fruit: each lies on the ground, on its table or in its tree's crown, at
 * the height that goes with the place, not inside a trunk, a table, the castle or (on the ground)
 * the river's water, and not inside another fruit. Part of the check behind
 * {@code World.fromScenario}; every rule is listed in {@code docs/scenarios.md}.
 */
final class FruitCheck {

    /** How far a resting fruit's height may differ from the exact one (rounding in files). */
    private static final double HEIGHT_TOLERANCE = 1e-6;

    private final World world;
    private final List<FruitState> all;
    private final List<String> problems = new ArrayList<>();

    FruitCheck(World world, List<FruitState> all) {
        this.world = world;
        this.all = all;
    }

    /** Every problem with the fruit, in the order of the fruit. */
    List<String> problems() {
        fruit();
        return problems;
    }

    private void fruit() {
        Obstacles obstacles = world.obstacleIndex();
        for (FruitState fruit : all) {
            String name = "fruit " + fruit.id();
            Vec3 at = fruit.position();
            double r = fruit.kind().radius();
            String support = fruit.support();
            Optional<Integer> held = support == null ? Optional.empty() : obstacles.indexOf(support);
            if (support != null && held.isEmpty()) {
                problems.add(name + " names support " + support + ", which is neither a tree nor a table");
                continue;
            }
            if (support == null) {
                expectHeight(name + " lies on the ground, so its centre must be at height " + Plane.format(r)
                        + " (its radius)", r, at.y());
            } else if (obstacles.isTree(held.get())) {
                hanging(name, at, r, world.trees().get(held.get()));
            } else {
                onTable(name, at, r, world.tables().get(held.get() - world.trees().size()));
            }
            inside(name, at, r, support == null);
        }
        overlappingFruit();
    }

    private void expectHeight(String rule, double expected, double actual) {
        if (Math.abs(actual - expected) > HEIGHT_TOLERANCE) {
            problems.add(rule + ", was " + Plane.format(actual));
        }
    }

    private void hanging(String name, Vec3 at, double r, Tree tree) {
        double distance = Math.hypot(at.x() - tree.position().x(), at.z() - tree.position().z());
        if (distance > tree.crownRadius() + Plane.EPSILON) {
            problems.add(name + " is not in the crown of tree " + tree.id() + ": it is " + Plane.format(distance)
                    + " from the trunk, the crown's radius is " + Plane.format(tree.crownRadius()));
        }
        if (at.y() - r < -HEIGHT_TOLERANCE) {
            problems.add(name + " hangs below the ground, at " + Plane.format(at.y()));
        } else if (at.y() + r > tree.height() + HEIGHT_TOLERANCE) {
            problems.add(name + " hangs at " + Plane.format(at.y()) + ", above the top of tree " + tree.id()
                    + " (height " + Plane.format(tree.height()) + ")");
        }
    }

    private void onTable(String name, Vec3 at, double r, Table table) {
        double distance = Math.hypot(at.x() - table.position().x(), at.z() - table.position().z());
        if (distance > table.radius() + Plane.EPSILON) {
            problems.add(name + " is not on table " + table.id() + ": it is " + Plane.format(distance)
                    + " from the table's centre, the top's radius is " + Plane.format(table.radius()));
        }
        expectHeight(name + " lies on table " + table.id() + ", so its centre must be at height "
                + Plane.format(table.height() + r) + " (the table's height plus the fruit's radius)",
                table.height() + r, at.y());
    }

    /** Whether the fruit's sphere is inside a trunk, a table, the castle or (on the ground) the river. */
    private void inside(String name, Vec3 at, double r, boolean onGround) {
        Obstacles obstacles = world.obstacleIndex();
        double margin = r + obstacles.maxBlockRadius;
        double bottom = at.y() - r;
        List<Integer> hits = new ArrayList<>();
        obstacles.grid.forEachInBox(at.x() - margin, at.z() - margin, at.x() + margin, at.z() + margin, i -> {
            double limit = obstacles.blockRadius[i] + r - Plane.EPSILON;
            double dx = obstacles.x[i] - at.x();
            double dz = obstacles.z[i] - at.z();
            double top = obstacles.records[i].height();
            if (dx * dx + dz * dz < limit * limit && bottom < top - HEIGHT_TOLERANCE) {
                hits.add(i);
            }
        });
        hits.sort(Comparator.naturalOrder());
        for (int i : hits) {
            problems.add(name + " is inside " + (obstacles.isTree(i) ? "the trunk of " : "") + obstacles.describe(i));
        }
        if (world.castle().region().touchedBy(at.x(), at.z(), at.x(), at.z(), r)
                && bottom < world.castle().height() - HEIGHT_TOLERANCE) {
            problems.add(name + " is inside the castle");
        }
        if (onGround && world.water().touchedBy(at.x(), at.z(), at.x(), at.z(), r)) {
            problems.add(name + " is in the river");
        }
    }

    /** Two fruit must not share space: a sweep along x over the spheres. */
    private void overlappingFruit() {
        List<FruitState> byX = new ArrayList<>(all);
        byX.sort(Comparator.comparingDouble((FruitState f) -> f.position().x()));
        double widest = 0;
        for (FruitState fruit : byX) {
            widest = Math.max(widest, fruit.kind().radius());
        }
        List<String> found = new ArrayList<>();
        for (int i = 0; i < byX.size(); i++) {
            FruitState a = byX.get(i);
            for (int j = i + 1; j < byX.size(); j++) {
                FruitState b = byX.get(j);
                if (b.position().x() - a.position().x() > 2 * widest) {
                    break;
                }
                double reach = a.kind().radius() + b.kind().radius() - Plane.EPSILON;
                Vec3 d = a.position().minus(b.position());
                if (d.x() * d.x() + d.y() * d.y() + d.z() * d.z() < reach * reach) {
                    FruitState first = all.indexOf(a) < all.indexOf(b) ? a : b;
                    FruitState second = first == a ? b : a;
                    found.add("fruit " + first.id() + " overlaps fruit " + second.id());
                }
            }
        }
        found.sort(Comparator.naturalOrder());
        problems.addAll(found);
    }
}
