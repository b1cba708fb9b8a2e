package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class PerceptionQueryTest {

    @Test
    void everythingWhoseCentreIsWithinRangeIsVisitedWithItsDistance() {
        World world = SmallWorld.builder()
                .tree("T1", 40, 30, 2, 6)
                .table("D1", 50, 50, 1, 0.9)
                .ground("F1", FruitKind.TOMATO, 30, 35)
                .world();
        List<String> seen = new ArrayList<>();

        world.visitWithin(30, 30, 15, new NearbyVisitor() {
            @Override
            public void obstacle(int index, Obstacle obstacle, double x, double z, double distance) {
                seen.add(obstacle.id() + "@" + distance);
            }

            @Override
            public void fruit(int index, FruitState fruit, double x, double z, double distance) {
                seen.add(fruit.id() + "@" + distance);
            }
        });

        assertThat(seen).containsExactlyInAnyOrder("T1@10.0", "F1@5.0");
    }

    @Test
    void anObjectExactlyAtTheRangeIsIncluded() {
        World world = SmallWorld.builder().tree("T1", 40, 30, 2, 6).world();

        assertThat(world.obstaclesWithin(new Point2(30, 30), 10)).extracting(Obstacle::id).containsExactly("T1");
        assertThat(world.obstaclesWithin(new Point2(30, 30), 9.99)).isEmpty();
    }

    @Test
    void theGridFindsTheSameAsLookingAtEverything() {
        World world = WorldGenerator.benchmark(5).generate();
        SplittableRandom random = new SplittableRandom(9);
        for (int probe = 0; probe < 200; probe++) {
            double x = random.nextDouble(-500, 500);
            double z = random.nextDouble(-500, 500);
            double range = random.nextDouble(1, 80);
            Set<String> expected = new HashSet<>();
            for (Obstacle obstacle : world.obstacles()) {
                if (Math.hypot(obstacle.position().x() - x, obstacle.position().z() - z) <= range) {
                    expected.add(obstacle.id());
                }
            }
            for (FruitState fruit : world.fruitStates()) {
                if (Math.hypot(fruit.position().x() - x, fruit.position().z() - z) <= range) {
                    expected.add(fruit.id());
                }
            }
            Set<String> found = new HashSet<>();
            world.visitWithin(x, z, range, new NearbyVisitor() {
                @Override
                public void obstacle(int index, Obstacle obstacle, double x, double z, double distance) {
                    assertThat(world.obstacles().get(index)).isSameAs(obstacle);
                    found.add(obstacle.id());
                }

                @Override
                public void fruit(int index, FruitState fruit, double x, double z, double distance) {
                    assertThat(world.allFruitStates().get(index)).isSameAs(fruit);
                    found.add(fruit.id());
                }
            });
            assertThat(found).as("around (%s, %s) within %s", x, z, range).isEqualTo(expected);
        }
    }

    @Test
    void aSightBoxKeepsEverythingInTheFieldOfView() {
        World world = WorldGenerator.benchmark(5).generate();
        SplittableRandom random = new SplittableRandom(11);
        for (int probe = 0; probe < 300; probe++) {
            double x = random.nextDouble(-500, 500);
            double z = random.nextDouble(-500, 500);
            double range = random.nextDouble(1, 80);
            double heading = random.nextDouble(-Math.PI, Math.PI);
            double field = random.nextDouble(0.2, 2 * Math.PI);
            double facingX = -Math.sin(heading);
            double facingZ = -Math.cos(heading);
            Set<String> expected = new HashSet<>();
            for (Obstacle obstacle : world.obstacles()) {
                if (inField(obstacle.position().x() - x, obstacle.position().z() - z, range, facingX, facingZ, field)) {
                    expected.add(obstacle.id());
                }
            }
            for (FruitState fruit : world.fruitStates()) {
                if (inField(fruit.position().x() - x, fruit.position().z() - z, range, facingX, facingZ, field)) {
                    expected.add(fruit.id());
                }
            }
            Set<String> found = new HashSet<>();
            world.visitWithin(x, z, range, SightBox.of(x, z, range, heading, field), new NearbyVisitor() {
                @Override
                public void obstacle(int index, Obstacle obstacle, double x, double z, double distance) {
                    found.add(obstacle.id());
                }

                @Override
                public void fruit(int index, FruitState fruit, double x, double z, double distance) {
                    found.add(fruit.id());
                }
            });
            assertThat(found).as("from (%s, %s) facing %s, field %s, range %s", x, z, heading, field, range)
                    .containsAll(expected);
        }
    }

    private static boolean inField(double dx, double dz, double range, double facingX, double facingZ, double field) {
        double distance = Math.hypot(dx, dz);
        return distance <= range && (field >= 2 * Math.PI || distance == 0
                || (dx * facingX + dz * facingZ) >= Math.cos(field / 2) * distance);
    }
}
