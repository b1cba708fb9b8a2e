package io.orchard.server.world;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;

/**
 * Places the fruit of a generated world, so that every fruit can be grasped. Each fruit is placed
 * together with a spot to grasp it from: a point where an agent of radius {@link #AGENT_RADIUS}
 * can stand with {@link #SPOT_SLACK} to spare on every side, from whose centre the fruit is at most
 * {@link #GRASP_DISTANCE} units plus its own radius away. So an agent of radius at most 0.5 whose
 * radius plus gripper reach is at least 0.9, standing anywhere within the slack of the spot and
 * facing the fruit, can grasp it if its gripper reaches the fruit's height.
 *
 * <p>Heights follow the place: a fruit on the ground lies at its radius (at most 0.35), one on a
 * table at the table's height plus its radius (at most 1.35), and one in a tree hangs between
 * {@link #LOWEST_HANGING} and {@link #HIGHEST_HANGING}, beside the trunk and under the crown.
 */
final class FruitLayout {

    /** The radius of the agent the fruit is placed for. */
    static final double AGENT_RADIUS = 0.5;

    /** How much free room the grasp spot has beyond that agent's radius. */
    static final double SPOT_SLACK = 0.1;

    /** The farthest a fruit's edge is from the centre of its grasp spot. */
    static final double GRASP_DISTANCE = 0.8;

    /** The lowest centre of a fruit hanging in a tree. */
    static final double LOWEST_HANGING = 1.5;

    /** The highest centre of a fruit hanging in a tree. */
    static final double HIGHEST_HANGING = 3.0;

    private static final double STAND = AGENT_RADIUS + SPOT_SLACK;
    private static final FruitKind[] KINDS = FruitKind.values();
    private static final int ATTEMPTS = 500;

    private final RandomGenerator random;
    private final World ground;
    private final List<FruitState> placed = new ArrayList<>();

    /** @param ground the generated world without its fruit */
    FruitLayout(RandomGenerator random, World ground) {
        this.random = random;
        this.ground = ground;
    }

    List<FruitState> make(int count) {
        for (int i = 1; i <= count; i++) {
            placed.add(one("F" + i));
        }
        return List.copyOf(placed);
    }

    private FruitState one(String id) {
        FruitKind kind = KINDS[random.nextInt(KINDS.length)];
        for (int attempt = 0; attempt < ATTEMPTS; attempt++) {
            double roll = random.nextDouble();
            boolean onTable = !ground.tables().isEmpty() && roll >= 0.4 && roll < 0.7;
            boolean inTree = !ground.trees().isEmpty() && roll >= 0.7;
            FruitState fruit = inTree ? inTree(id, kind) : onTable ? onTable(id, kind) : onGround(id, kind);
            if (fruit != null && clearOfOtherFruit(fruit)) {
                return fruit;
            }
        }
        throw new IllegalStateException("could not place fruit " + id + " after " + ATTEMPTS
                + " attempts: the world is too crowded; ask for less fruit or a larger world");
    }

    private FruitState onGround(String id, FruitKind kind) {
        double x = uniform(ground.bounds().minX(), ground.bounds().maxX());
        double z = uniform(ground.bounds().minZ(), ground.bounds().maxZ());
        if (!standable(x, z)) {
            return null;
        }
        double r = kind.radius();
        double direction = uniform(0, 2 * Math.PI);
        double distance = uniform(AGENT_RADIUS + r, GRASP_DISTANCE + r);
        Point2 at = rounded(x + StrictMath.cos(direction) * distance, z + StrictMath.sin(direction) * distance);
        if (!ground.checkPlace(at, r).isFree()) {
            return null;
        }
        return new FruitState(id, kind, at.at(r), null);
    }

    private FruitState onTable(String id, FruitKind kind) {
        Table table = ground.tables().get(random.nextInt(ground.tables().size()));
        double r = kind.radius();
        double direction = uniform(0, 2 * Math.PI);
        double cos = StrictMath.cos(direction);
        double sin = StrictMath.sin(direction);
        double spot = table.radius() + STAND + 0.02;
        if (!standable(table.position().x() + cos * spot, table.position().z() + sin * spot)) {
            return null;
        }
        // Near the edge facing the spot: at most 0.15 in from where the fruit's edge meets the table's.
        double fromCentre = Math.max(0, table.radius() - r - uniform(0, 0.15));
        Point2 at = rounded(table.position().x() + cos * fromCentre, table.position().z() + sin * fromCentre);
        return new FruitState(id, kind, at.at(RiverLayout.round(table.height() + r)), table.id());
    }

    private FruitState inTree(String id, FruitKind kind) {
        Tree tree = ground.trees().get(random.nextInt(ground.trees().size()));
        double r = kind.radius();
        double direction = uniform(0, 2 * Math.PI);
        double cos = StrictMath.cos(direction);
        double sin = StrictMath.sin(direction);
        double spot = tree.trunkRadius() + STAND + 0.02;
        if (!standable(tree.position().x() + cos * spot, tree.position().z() + sin * spot)) {
            return null;
        }
        double fromCentre = Math.min(tree.crownRadius(), tree.trunkRadius() + r + uniform(0.05, 0.3));
        Point2 at = rounded(tree.position().x() + cos * fromCentre, tree.position().z() + sin * fromCentre);
        double highest = Math.min(HIGHEST_HANGING, tree.height() - r);
        if (highest < LOWEST_HANGING || !ground.checkPlace(at, r).isFree()) {
            return null;
        }
        double y = RiverLayout.round(uniform(LOWEST_HANGING, highest));
        return new FruitState(id, kind, at.at(y), tree.id());
    }

    private boolean standable(double x, double z) {
        return ground.checkPlace(new Point2(x, z), STAND).isFree();
    }

    private boolean clearOfOtherFruit(FruitState fruit) {
        for (FruitState other : placed) {
            Vec3 d = other.position().minus(fruit.position());
            double limit = other.kind().radius() + fruit.kind().radius() + 0.05;
            if (d.x() * d.x() + d.y() * d.y() + d.z() * d.z() < limit * limit) {
                return false;
            }
        }
        return true;
    }

    private static Point2 rounded(double x, double z) {
        return new Point2(RiverLayout.round(x), RiverLayout.round(z));
    }

    private double uniform(double from, double to) {
        return from + (to - from) * random.nextDouble();
    }
}
