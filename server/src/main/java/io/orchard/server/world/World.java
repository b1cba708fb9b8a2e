package io.orchard.server.world;

import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.random.RandomGenerator;
import org.locationtech.jts.geom.Geometry;

/**
 * The world model of the paper: the ground agents walk on, its trees, tables, castle, river and
 * bridges, and the fruit still there. The server uses it to decide whether a move puts an agent in
 * an impossible place, what an agent perceives and whether a grasp reaches its fruit.
 *
 * <p>The static things never change: their geometry is prepared and indexed once, when the world is
 * made. The fruit is the only mutable part, and it only shrinks: {@link #removeFruit} takes a
 * fruit away.
 *
 * <p><b>Not thread-safe.</b> A world belongs to one thread, the simulation's tick thread; other
 * threads hand their requests to that thread instead of calling the world themselves.
 *
 * <p>A world is made from a {@link Scenario} (read from a file or made by a {@link WorldGenerator})
 * and turned back into one by {@link #toScenario()}: the scenario is the world's value, so two
 * worlds are alike when their scenarios are equal.
 */
public final class World {

    private static final int FREE_POINT_ATTEMPTS = 1000;

    private final Bounds bounds;
    private final Obstacles obstacles;
    private final Castle castle;
    private final River river;
    private final List<Bridge> bridges;
    private final Region water;
    private final MoveCheck moves;
    private final Sightline sight;
    private final FruitStore fruit;
    private final List<Obstacle> obstacleList;

    World(Bounds bounds, List<Tree> trees, List<Table> tables, Castle castle, River river, List<Bridge> bridges,
          List<Fruit> fruit) {
        this.bounds = bounds;
        this.obstacles = new Obstacles(bounds, trees, tables);
        this.castle = castle;
        this.river = river;
        this.bridges = List.copyOf(bridges);
        this.water = new Region(uncovered(river, this.bridges));
        this.moves = new MoveCheck(bounds, obstacles, castle.region(), water);
        this.sight = new Sightline(castle);
        this.fruit = new FruitStore(bounds, fruit);
        this.obstacleList = List.of(obstacles.records);
    }

    /** A world with the static things of {@code shared} and fruit of its own. */
    private World(World shared, FruitStore fruit) {
        this.bounds = shared.bounds;
        this.obstacles = shared.obstacles;
        this.castle = shared.castle;
        this.river = shared.river;
        this.bridges = shared.bridges;
        this.water = shared.water;
        this.moves = shared.moves;
        this.sight = shared.sight;
        this.fruit = fruit;
        this.obstacleList = shared.obstacleList;
    }

    /**
     * A world with this one's trees, tables, castle, river and bridges, which never change and are
     * shared, not copied, and a store of its own of the fruit this one has now, in the same spatial
     * index (so that the two visit the fruit near a point in the same order). Taking a fruit
     * from one leaves the other's. For a program that holds parts of one world on several threads:
     * each part's world may be read on its own thread while the others are read on theirs.
     */
    public World withOwnFruit() {
        return new World(this, fruit.copy());
    }

    /** The river without the decks of its bridges: the water agents must keep out of. */
    private static Geometry uncovered(River river, List<Bridge> bridges) {
        List<Geometry> decks = new ArrayList<>();
        for (Bridge bridge : bridges) {
            decks.add(bridge.polygon());
        }
        Geometry covered = Shapes.FACTORY.buildGeometry(decks).union();
        return river.polygon().difference(covered);
    }

    /**
     * Makes the world a scenario describes, after checking that its things fit together.
     *
     * @throws ScenarioException naming every object that does not fit and why: overlaps, things
     *                           outside the world, fruit inside obstacles, a river without a
     *                           bridge... (see {@code docs/scenarios.md})
     */
    public static World fromScenario(Scenario scenario) {
        return ScenarioCheck.build(scenario);
    }

    /** This world as a scenario, with the fruit still there: write it out to replay this state. */
    public Scenario toScenario() {
        List<BridgeShape> bridgeShapes = bridges.stream().map(Bridge::shape).toList();
        List<Obstacle> trees = obstacleList.subList(0, obstacles.trees.size());
        List<Obstacle> tables = obstacleList.subList(obstacles.trees.size(), obstacleList.size());
        return new Scenario(Scenario.FORMAT, bounds, castle.shape(), river.shape(), bridgeShapes, trees, tables,
                fruit.states());
    }

    // ---- the things -----------------------------------------------------------------------------

    /** The rectangle agents may walk on. */
    public Bounds bounds() {
        return bounds;
    }

    /** The trees, of the forest and the open land. */
    public List<Tree> trees() {
        return obstacles.trees;
    }

    /** The tables. */
    public List<Table> tables() {
        return obstacles.tables;
    }

    /** The trees and then the tables, as the protocol describes them. */
    public List<Obstacle> obstacles() {
        return obstacleList;
    }

    /** The castle. */
    public Castle castle() {
        return castle;
    }

    /** The river. */
    public River river() {
        return river;
    }

    /** The bridges over the river. */
    public List<Bridge> bridges() {
        return bridges;
    }

    /** The tree or table with this id. */
    public Optional<Obstacle> obstacle(String id) {
        return obstacles.indexOf(id).map(i -> obstacles.records[i]);
    }

    /** The fruit still there, in the order the world was made with. */
    public List<Fruit> fruit() {
        return fruit.list();
    }

    /** The fruit still there as the protocol describes it, for viewers. */
    public List<FruitState> fruitStates() {
        return fruit.states();
    }

    /**
     * Every fruit the world was made with, taken or not, in order: what the fruit indices of a
     * {@link NearbyVisitor} refer to.
     */
    public List<FruitState> allFruitStates() {
        return fruit.allStates();
    }

    /** The fruit with this id, if it is still there. */
    public Optional<Fruit> fruit(String id) {
        return fruit.get(id);
    }

    /** How many fruit are still there. */
    public int fruitCount() {
        return fruit.remaining();
    }

    /**
     * Takes a fruit out of the world.
     *
     * @return whether it was there to take
     */
    public boolean removeFruit(String id) {
        return fruit.remove(id);
    }

    // ---- movement -------------------------------------------------------------------------------

    /**
     * May an agent of this radius move in a straight line from one point to the other? The disc
     * swept along the segment must stay inside the world and clear of tree trunks, tables and the
     * castle, and may be over the river only on a bridge's deck. Heights do not matter.
     *
     * @return free, or what the agent would meet first: "path crosses tree T17", "path crosses table
     *     D2", "path enters the castle", "path enters the river outside a bridge", "path leaves the
     *     world"
     */
    public MoveResult checkMove(Point2 from, Point2 to, double radius) {
        return moves.check(from.x(), from.z(), to.x(), to.z(), radius);
    }

    /**
     * May an agent of this radius stand here? The same rules as {@link #checkMove} for a move of
     * length zero; the reasons say "position" ("position overlaps tree T17").
     */
    public MoveResult checkPlace(Point2 at, double radius) {
        return moves.check(at.x(), at.z(), at.x(), at.z(), radius);
    }

    // ---- sight and landmarks --------------------------------------------------------------------

    /**
     * Whether the castle leaves a clear line of sight between two ground points. Only the castle
     * hides things (trees and tables do not), and it hides them whatever their height; a sight line
     * that only grazes a wall is clear.
     */
    public boolean lineOfSight(Point2 from, Point2 to) {
        return sight.clear(from.x(), from.z(), to.x(), to.z());
    }

    /**
     * Whether the castle may hide anything within {@code range} of a point: false when it lies wholly
     * farther away, so that a perception need not test its sight lines one by one.
     */
    public boolean castleNear(Point2 from, double range) {
        return sight.near(from.x(), from.z(), range);
    }

    /** Whether the castle hides one ground point from the other: the opposite of {@link #lineOfSight}. */
    public boolean castleHides(Point2 from, Point2 to) {
        return !lineOfSight(from, to);
    }

    /**
     * The compass sector the castle lies in as seen from a point: the direction from the point to
     * the centre of the castle's footprint. This is all an agent perceives of the castle.
     */
    public Sector castleSector(Point2 from) {
        return Sector.of(castle.centre().x() - from.x(), castle.centre().z() - from.z());
    }

    /**
     * Whether the whole river lies farther than {@code range} from a point, so that
     * {@link #nearestRiverPoint} need not be asked. A cheap test that may answer no for a river
     * just out of range.
     */
    public boolean riverBeyond(Point2 from, double range) {
        return river.beyond(from.x(), from.z(), range);
    }

    /** The nearest point of the river to a point, and the direction the river runs there. */
    public RiverPoint nearestRiverPoint(Point2 from) {
        return river.nearest(from.x(), from.z());
    }

    /**
     * The bank of the river a point is on; empty when it is in the river (in the water or on a
     * bridge over it) or outside the world. Two points on the same bank can be joined without a
     * bridge (unless obstacles are in the way); points on different banks cannot.
     */
    public Optional<Bank> bankOf(Point2 point) {
        return river.bankOf(point.x(), point.z());
    }

    /** The bridge whose deck a point is on, if any. */
    public Optional<Bridge> bridgeAt(Point2 point) {
        for (Bridge bridge : bridges) {
            if (bridge.covers(point.x(), point.z())) {
                return Optional.of(bridge);
            }
        }
        return Optional.empty();
    }

    /** Whether a point is on a bridge's deck. */
    public boolean onBridge(Point2 point) {
        return bridgeAt(point).isPresent();
    }

    // ---- perception -----------------------------------------------------------------------------

    /**
     * Gives the visitor every tree, table and fruit whose centre lies within {@code range} of
     * (x, z) on the ground, with its distance. The caller applies the field of view. Allocates
     * nothing per object: built for every agent on every tick.
     */
    public void visitWithin(double x, double z, double range, NearbyVisitor visitor) {
        visitWithin(x, z, range, SightBox.around(x, z, range), visitor);
    }

    /**
     * As {@link #visitWithin(double, double, double, NearbyVisitor)}, but only for what lies in
     * {@code box} as well: give the {@link SightBox} of an agent's field of view, and the world
     * visits only the part of the circle the agent faces.
     */
    public void visitWithin(double x, double z, double range, SightBox box, NearbyVisitor visitor) {
        Checks.finite(x, "x");
        Checks.finite(z, "z");
        Checks.nonNegative(range, "range");
        Checks.present(box, "box");
        Checks.present(visitor, "visitor");
        double rangeSq = range * range;
        Obstacle[] records = obstacles.records;
        obstacles.grid.forEachInBox(box.minX(), box.minZ(), box.maxX(), box.maxZ(), (i, atX, atZ) -> {
            double dx = atX - x;
            double dz = atZ - z;
            double distanceSq = dx * dx + dz * dz;
            if (distanceSq <= rangeSq) {
                visitor.obstacle(i, records[i], atX, atZ, Math.sqrt(distanceSq));
            }
        });
        fruit.visitWithin(x, z, range, box, visitor);
    }

    /** The trees and tables whose centre lies within {@code range} of a point; a convenience for tests and tools. */
    public List<Obstacle> obstaclesWithin(Point2 centre, double range) {
        List<Obstacle> found = new ArrayList<>();
        visitWithin(centre.x(), centre.z(), range, new NearbyVisitor() {
            @Override
            public void obstacle(int index, Obstacle obstacle, double x, double z, double distance) {
                found.add(obstacle);
            }
        });
        return found;
    }

    /** The fruit whose centre lies within {@code range} of a point; a convenience for tests and tools. */
    public List<FruitState> fruitWithin(Point2 centre, double range) {
        List<FruitState> found = new ArrayList<>();
        visitWithin(centre.x(), centre.z(), range, new NearbyVisitor() {
            @Override
            public void fruit(int index, FruitState state, double x, double z, double distance) {
                found.add(state);
            }
        });
        return found;
    }

    // ---- grasping -------------------------------------------------------------------------------

    /**
     * Whether an agent standing at {@code position} with this heading and body can grasp a fruit:
     * see {@link Reach} for the rule and its reasons ("fruit F3 is 2.4 units away, reach is 1.2",
     * "fruit F3 hangs at 2.8, gripper reaches 0.0–0.6"). Does not take the fruit: the caller
     * decides between competing agents and then calls {@link #removeFruit}.
     */
    public ReachResult reach(Vec3 position, double heading, Body body, Fruit fruit) {
        Checks.present(fruit, "fruit");
        boolean hanging = fruit.support() != null
                && obstacles.indexOf(fruit.support()).map(obstacles::isTree).orElse(false);
        return Reach.check(fruit, hanging, position, heading, body);
    }

    // ---- placing agents and describing the world ------------------------------------------------

    /**
     * A point on the ground where an agent of this radius may stand ({@link #checkPlace} is free),
     * drawn uniformly from the world by the given generator; null when a thousand draws found none.
     * Deterministic for a seeded generator.
     */
    public Vec3 randomFreePoint(RandomGenerator random, double radius) {
        Checks.present(random, "random");
        Checks.positive(radius, "radius");
        for (int attempt = 0; attempt < FREE_POINT_ATTEMPTS; attempt++) {
            double x = bounds.minX() + random.nextDouble() * bounds.width();
            double z = bounds.minZ() + random.nextDouble() * bounds.depth();
            if (moves.check(x, z, x, z, radius).isFree()) {
                return Vec3.ground(x, z);
            }
        }
        return null;
    }

    /** Everything a viewer needs to show this world, with the clock and the scores it is given. */
    public WorldSnapshotMessage snapshot(long tick, double time, List<Score> scores) {
        return new WorldSnapshotMessage(tick, time, bounds, obstacles(), castle.shape(), river.shape(),
                bridges.stream().map(Bridge::shape).toList(), fruit.states(), scores);
    }

    // ---- for the scenario check -----------------------------------------------------------------

    Obstacles obstacleIndex() {
        return obstacles;
    }

    Region water() {
        return water;
    }
}
