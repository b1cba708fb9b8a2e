package io.orchard.server.world;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.server.world.scenario.Scenario;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;

/**
 * Makes a world from a random generator: a square garden centred on the origin with a river across
 * it, two bridges, a castle, a forest, some tables and fruit on the ground, on the tables and in
 * the trees. The same seed and options make the same world, to the last digit and on any JVM
 * (the layout uses {@link StrictMath} and rounds coordinates to thousandths); nothing else (no
 * clock, no global random) is consulted.
 *
 * <p>What a generated world guarantees, beyond what every scenario must satisfy:
 * <ul>
 *   <li>a tree's trunk keeps {@link #TREE_CLEARANCE} units from every other trunk and table, a
 *       table keeps {@link #TABLE_CLEARANCE}; both keep the same from the castle,
 *       {@link #RIVER_CLEARANCE} from the river, {@link #BRIDGE_CLEARANCE} from a bridge's deck and
 *       {@link #EDGE_CLEARANCE} from the world's edge, so an agent of radius 0.5 can walk between
 *       any two of them;
 *   <li>the castle keeps 12 units from the river and the bridges and 10 from the world's edge;
 *   <li>every fruit can be grasped by an agent of radius at most 0.5 whose radius plus gripper
 *       reach is at least 0.9 and whose gripper reaches the fruit's height, standing on free ground
 *       next to it: fruit on the ground lies at most 0.35 high, on a table at most 1.35, in a tree
 *       between 1.5 and 3.0.
 * </ul>
 *
 * <p>About 60 % of the trees stand in "the forest", a disc with room for about
 * {@link #FOREST_AREA_PER_TREE} square units per tree; the rest are spread over the world.
 *
 * <p>Each call to {@link #generate()} draws further from the random generator: to make a world
 * again, make a new generator with the same seed. Not thread-safe.
 */
public final class WorldGenerator {

    /** The least gap between a tree's trunk and any other trunk, table or the castle. */
    public static final double TREE_CLEARANCE = 1.5;

    /** The least gap between a table and any trunk, other table or the castle. */
    public static final double TABLE_CLEARANCE = 2.0;

    /** The least gap between a trunk or table and the river. */
    public static final double RIVER_CLEARANCE = 2.0;

    /** The least gap between a trunk or table and a bridge's deck, so that bridges can be reached. */
    public static final double BRIDGE_CLEARANCE = 3.0;

    /** The least gap between a trunk or table and the world's edge. */
    public static final double EDGE_CLEARANCE = 1.5;

    /** The share of the trees that stand in the forest. */
    public static final double FOREST_SHARE = 0.6;

    /** Square units of forest per forest tree: about one tree every 6 or 7 units. */
    public static final double FOREST_AREA_PER_TREE = 40;

    private final RandomGenerator random;
    private final WorldOptions options;

    /**
     * A generator of worlds as {@code options} describe them.
     *
     * @param random  where every random choice comes from; seed it to make the same world again
     * @param options what to make
     */
    public WorldGenerator(RandomGenerator random, WorldOptions options) {
        this.random = Objects.requireNonNull(random, "random");
        this.options = Objects.requireNonNull(options, "options");
    }

    /** A generator of the paper's garden ({@link WorldOptions#DEFAULT}) from a seed. */
    public static WorldGenerator standard(long seed) {
        return new WorldGenerator(new SplittableRandom(seed), WorldOptions.DEFAULT);
    }

    /** A generator of a benchmark world ({@link WorldOptions#BENCHMARK}) from a seed. */
    public static WorldGenerator benchmark(long seed) {
        return new WorldGenerator(new SplittableRandom(seed), WorldOptions.BENCHMARK);
    }

    /** Makes a world. */
    public World generate() {
        return World.fromScenario(scenario());
    }

    /**
     * Makes a world and gives it as a scenario, ready to be written to a file.
     *
     * @throws IllegalStateException in the unlikely case that the options leave too little room to
     *                               place everything with its clearances
     */
    public Scenario scenario() {
        double half = options.size() / 2;
        Bounds bounds = new Bounds(-half, -half, half, half);
        RiverLayout.Layout layout = new RiverLayout(random, bounds).make();
        River river = new River(layout.river(), bounds);
        List<Region> decks = layout.bridges().stream().map(bridge -> new Region(new Bridge(bridge).polygon())).toList();
        List<Region> water = new ArrayList<>(decks);
        water.add(river.region());
        CastleShape castleShape = new CastleLayout(random, bounds).make(water);
        Castle castle = new Castle(castleShape);
        Grove grove = new Grove(random, bounds, castle.region(), river.region(), decks);
        List<Obstacle> trees = grove.trees(options.trees(), castle.centre());
        List<Obstacle> tables = grove.tables(options.tables());
        Scenario bare = new Scenario(Scenario.FORMAT, bounds, castleShape, layout.river(), layout.bridges(), trees,
                tables, List.of());
        List<FruitState> fruit = new FruitLayout(random, World.fromScenario(bare)).make(options.fruit());
        return new Scenario(Scenario.FORMAT, bounds, castleShape, layout.river(), layout.bridges(), trees, tables,
                fruit);
    }
}
