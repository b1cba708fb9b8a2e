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
            public void obstacle(Obstacle obstacle, double distance) {
                seen.add(obstacle.id() + "@" + distance);
            }

            @Override
            public void fruit(FruitState fruit, double distance) {
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
                public void obstacle(Obstacle obstacle, double distance) {
                    found.add(obstacle.id());
                }

                @Override
                public void fruit(FruitState fruit, double distance) {
                    found.add(fruit.id());
                }
            });
            assertThat(found).as("around (%s, %s) within %s", x, z, range).isEqualTo(expected);
        }
    }
}
