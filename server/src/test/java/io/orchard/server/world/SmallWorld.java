package io.orchard.server.world;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.scenario.Scenario;
import java.util.ArrayList;
import java.util.List;

/**
 * Builds small worlds whose every distance is known. Unless changed: the world is x 0..100 by
 * z 0..100; the river runs east-west over z 60..70; bridge B1 crosses it at x = 50 from z = 57 to
 * z = 73, 4 wide (its deck covers x 48..52); the castle is the square x 10..20, z 10..20, 10 high.
 * Trees, tables and fruit are added by the test.
 */
final class SmallWorld {

    /** A short agent: radius 0.4, gripper reaching 0.5 beyond its body, from the ground to 0.6. */
    static final Body SHORT = body(0.4, 0.5, 0, 0.6);

    /** A medium agent: radius 0.5, reaching 0.5, from the ground to 1.5. */
    static final Body MEDIUM = body(0.5, 0.5, 0, 1.5);

    /** A tall agent: radius 0.5, reaching 0.6, from the ground to 3.2. */
    static final Body TALL = body(0.5, 0.6, 0, 3.2);

    private Bounds bounds = new Bounds(0, 0, 100, 100);
    private CastleShape castle = new CastleShape(points(10, 10, 20, 10, 20, 20, 10, 20), 10);
    private RiverShape river = new RiverShape(points(0, 60, 100, 60, 100, 70, 0, 70));
    private List<BridgeShape> bridges = List.of(new BridgeShape("B1", new Point2(50, 57), new Point2(50, 73), 4));
    private final List<Obstacle> trees = new ArrayList<>();
    private final List<Obstacle> tables = new ArrayList<>();
    private final List<FruitState> fruit = new ArrayList<>();

    static SmallWorld builder() {
        return new SmallWorld();
    }

    static Body body(double radius, double reach, double minHeight, double maxHeight) {
        return new Body(radius, 1.8, 5, new Gripper("hands", reach, minHeight, maxHeight), new Sight(30, Math.PI));
    }

    /** Ground points from x, z pairs. */
    static List<Point2> points(double... xz) {
        List<Point2> points = new ArrayList<>();
        for (int i = 0; i < xz.length; i += 2) {
            points.add(new Point2(xz[i], xz[i + 1]));
        }
        return points;
    }

    SmallWorld bounds(Bounds newBounds) {
        this.bounds = newBounds;
        return this;
    }

    SmallWorld castle(double height, double... xz) {
        this.castle = new CastleShape(points(xz), height);
        return this;
    }

    SmallWorld river(double... xz) {
        this.river = new RiverShape(points(xz));
        return this;
    }

    SmallWorld bridges(BridgeShape... newBridges) {
        this.bridges = List.of(newBridges);
        return this;
    }

    SmallWorld tree(String id, double x, double z, double crown, double height) {
        trees.add(new Obstacle(id, ObjectKind.TREE, new Point2(x, z), crown, height));
        return this;
    }

    SmallWorld table(String id, double x, double z, double radius, double height) {
        tables.add(new Obstacle(id, ObjectKind.TABLE, new Point2(x, z), radius, height));
        return this;
    }

    /** Any obstacle in any list, to test the lists' checks. */
    SmallWorld treeListEntry(Obstacle obstacle) {
        trees.add(obstacle);
        return this;
    }

    SmallWorld fruit(String id, FruitKind kind, double x, double y, double z, String support) {
        fruit.add(new FruitState(id, kind, new Vec3(x, y, z), support));
        return this;
    }

    /** A fruit lying on the ground at (x, z). */
    SmallWorld ground(String id, FruitKind kind, double x, double z) {
        return fruit(id, kind, x, kind.radius(), z, null);
    }

    Scenario scenario() {
        return new Scenario(Scenario.FORMAT, bounds, castle, river, bridges, trees, tables, fruit);
    }

    World world() {
        return World.fromScenario(scenario());
    }
}
