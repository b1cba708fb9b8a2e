package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.scenario.Scenario;
import java.util.List;
import java.util.Random;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

class WorldGeneratorTest {

    private static final double SLACK = 1e-9;

    static LongStream fiftySeeds() {
        return LongStream.rangeClosed(1, 50);
    }

    static LongStream twentySeeds() {
        return LongStream.rangeClosed(101, 120);
    }

    @Test
    void theSameSeedMakesTheSameWorld() {
        assertThat(WorldGenerator.standard(42).scenario()).isEqualTo(WorldGenerator.standard(42).scenario());
        assertThat(new WorldGenerator(new Random(7), WorldOptions.DEFAULT).scenario())
                .isEqualTo(new WorldGenerator(new Random(7), WorldOptions.DEFAULT).scenario());
    }

    @Test
    void differentSeedsMakeDifferentWorlds() {
        assertThat(WorldGenerator.standard(1).scenario()).isNotEqualTo(WorldGenerator.standard(2).scenario());
    }

    @Test
    void theDefaultWorldHasThePapersThings() {
        World world = WorldGenerator.standard(3).generate();

        assertThat(world.bounds().width()).isEqualTo(200);
        assertThat(world.bounds().depth()).isEqualTo(200);
        assertThat(world.trees()).hasSize(40);
        assertThat(world.tables()).hasSize(6);
        assertThat(world.fruit()).hasSize(30);
        assertThat(world.bridges()).extracting(Bridge::id).containsExactly("B1", "B2");
        assertThat(world.river().banks()).hasSize(2);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("fiftySeeds")
    void aGeneratedWorldKeepsItsClearances(long seed) {
        World world = WorldGenerator.standard(seed).generate(); // fromScenario already refuses any overlap
        List<Tree> trees = world.trees();
        List<Table> tables = world.tables();

        for (int i = 0; i < trees.size(); i++) {
            Tree tree = trees.get(i);
            for (int j = i + 1; j < trees.size(); j++) {
                assertThat(gap(tree.position(), tree.trunkRadius(), trees.get(j).position(), trees.get(j).trunkRadius()))
                        .as("%s and %s", tree.id(), trees.get(j).id())
                        .isGreaterThanOrEqualTo(WorldGenerator.TREE_CLEARANCE - SLACK);
            }
            for (Table table : tables) {
                assertThat(gap(tree.position(), tree.trunkRadius(), table.position(), table.radius()))
                        .as("%s and %s", tree.id(), table.id())
                        .isGreaterThanOrEqualTo(WorldGenerator.TABLE_CLEARANCE - SLACK);
            }
            assertKeepsClear(world, tree.id(), tree.position(), tree.trunkRadius(), WorldGenerator.TREE_CLEARANCE);
        }
        for (Table table : tables) {
            assertKeepsClear(world, table.id(), table.position(), table.radius(), WorldGenerator.TABLE_CLEARANCE);
        }
        for (int i = 0; i < tables.size(); i++) {
            for (int j = i + 1; j < tables.size(); j++) {
                assertThat(gap(tables.get(i).position(), tables.get(i).radius(), tables.get(j).position(),
                        tables.get(j).radius())).isGreaterThanOrEqualTo(WorldGenerator.TABLE_CLEARANCE - SLACK);
            }
        }
        for (Fruit fruit : world.fruit()) {
            double y = fruit.position().y();
            if (fruit.onGround()) {
                assertThat(world.checkPlace(fruit.position().onGround(), fruit.radius()).isFree()).as(fruit.id()).isTrue();
                assertThat(y).isEqualTo(fruit.radius());
            } else if (fruit.support().startsWith("T")) {
                assertThat(y).as(fruit.id()).isBetween(1.5, 3.0);
            } else {
                Table table = tables.stream().filter(t -> t.id().equals(fruit.support())).findFirst().orElseThrow();
                assertThat(y).as(fruit.id()).isCloseTo(table.height() + fruit.radius(), org.assertj.core.api.Assertions.within(1e-9));
            }
        }
    }

    private static void assertKeepsClear(World world, String id, Point2 at, double radius, double fromCastle) {
        double x = at.x();
        double z = at.z();
        assertThat(world.castle().region().touchedBy(x, z, x, z, radius + fromCastle - SLACK)).as(id).isFalse();
        assertThat(world.river().region().touchedBy(x, z, x, z, radius + WorldGenerator.RIVER_CLEARANCE - SLACK))
                .as(id).isFalse();
        for (Bridge bridge : world.bridges()) {
            assertThat(new Region(bridge.polygon()).touchedBy(x, z, x, z, radius + WorldGenerator.BRIDGE_CLEARANCE - SLACK))
                    .as("%s and %s", id, bridge.id()).isFalse();
        }
        assertThat(world.checkPlace(at, radius + WorldGenerator.EDGE_CLEARANCE - SLACK).obstruction())
                .as(id).isNotEqualTo(MoveResult.Obstruction.EDGE);
    }

    private static double gap(Point2 a, double ra, Point2 b, double rb) {
        return a.distance(b) - ra - rb;
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("fiftySeeds")
    void aGeneratedWorldHasAForest(long seed) {
        World world = WorldGenerator.standard(seed).generate();
        // Spread evenly, a tree would have fewer than one neighbour within 15 units; in the forest, many.
        long densest = world.trees().stream()
                .mapToLong(tree -> world.trees().stream().filter(o -> o.position().distance(tree.position()) <= 15).count())
                .max().orElse(0);

        assertThat(densest).isGreaterThanOrEqualTo(8);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("twentySeeds")
    void everyFruitCanBeGraspedByAShortAMediumOrATallAgent(long seed) {
        World world = WorldGenerator.standard(seed).generate();

        for (Fruit fruit : world.fruit()) {
            assertThat(graspable(world, fruit, SmallWorld.SHORT) || graspable(world, fruit, SmallWorld.MEDIUM)
                    || graspable(world, fruit, SmallWorld.TALL))
                    .as("fruit %s (%s) at %s", fruit.id(), fruit.support(), fruit.position())
                    .isTrue();
        }
    }

    @Test
    void everyGroundFruitCanBeGraspedByTheShortAgentAndEveryTableFruitByTheMediumOne() {
        for (long seed = 200; seed < 205; seed++) {
            World world = WorldGenerator.standard(seed).generate();
            for (Fruit fruit : world.fruit()) {
                if (fruit.onGround()) {
                    assertThat(graspable(world, fruit, SmallWorld.SHORT)).as(fruit.id()).isTrue();
                } else if (fruit.support().startsWith("D")) {
                    assertThat(graspable(world, fruit, SmallWorld.MEDIUM)).as(fruit.id()).isTrue();
                }
            }
        }
    }

    /** Whether some free place near the fruit lets this body grasp it, facing it. */
    static boolean graspable(World world, Fruit fruit, Body body) {
        if (!body.gripper().reachesHeight(fruit.position().y())) {
            return false;
        }
        double limit = body.radius() + body.gripper().reach() + fruit.radius();
        for (double distance = 0; distance <= limit; distance += 0.05) {
            for (int degrees = 0; degrees < 360; degrees += 3) {
                double angle = Math.toRadians(degrees);
                double x = fruit.position().x() + Math.cos(angle) * distance;
                double z = fruit.position().z() + Math.sin(angle) * distance;
                if (!world.checkPlace(new Point2(x, z), body.radius()).isFree()) {
                    continue;
                }
                double heading = Math.atan2(-(fruit.position().x() - x), -(fruit.position().z() - z));
                if (world.reach(Vec3.ground(x, z), heading, body, fruit).reachable()) {
                    return true;
                }
            }
        }
        return false;
    }

    @Test
    void aBenchmarkWorldHasTenThousandObjects() {
        World world = WorldGenerator.benchmark(1).generate();

        assertThat(world.bounds().width()).isEqualTo(1000);
        assertThat(world.trees().size() + world.tables().size() + world.fruitCount()).isEqualTo(10_000);
    }

    @Test
    void biggerOptionsMakeABiggerWorld() {
        Scenario scenario = new WorldGenerator(new Random(1), WorldOptions.DEFAULT.withSize(400).withTrees(300)
                .withTables(20).withFruit(100)).scenario();

        assertThat(scenario.bounds().width()).isEqualTo(400);
        assertThat(scenario.trees()).hasSize(300);
        assertThat(scenario.tables()).hasSize(20);
        assertThat(scenario.fruit()).hasSize(100);
    }

    @Test
    void aWorldWithoutTreesOrTablesPutsAllFruitOnTheGround() {
        World world = new WorldGenerator(new Random(1), new WorldOptions(150, 0, 0, 20)).generate();

        assertThat(world.fruit()).hasSize(20).allMatch(Fruit::onGround);
    }

    @ParameterizedTest(name = "{4}")
    @CsvSource(delimiter = '|', textBlock = """
            50   | 40    | 6    | 30   | size must be between 100 and 10000 units, was 50.0
            NaN  | 40    | 6    | 30   | size must be a finite number, was NaN
            200  | -1    | 6    | 30   | trees must not be negative, was -1
            200  | 40    | -2   | 30   | tables must not be negative, was -2
            200  | 40    | 6    | -3   | fruit must not be negative, was -3
            200  | 700   | 200  | 30   | too many trees and tables for a world of 200.0 x 200.0: 900 asked, at most 800
            200  | 40    | 6    | 900  | too much fruit for a world of 200.0 x 200.0: 900 asked, at most 800
            """)
    void impossibleOptionsAreRefusedWithTheReason(double size, int trees, int tables, int fruit, String message) {
        assertThatThrownBy(() -> new WorldOptions(size, trees, tables, fruit))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage(message);
    }
}
