package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Point2;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The cheap "is the river out of sight?" test never hides a river that is in range. */
class RiverBeyondTest {

    @Test
    void saysBeyondOnlyWhenTheNearestWaterIsFartherThanTheRange() {
        World world = WorldGenerator.standard(1998).generate();
        Random random = new Random(3);
        int beyond = 0;
        int trials = 20_000;
        for (int i = 0; i < trials; i++) {
            Point2 at = new Point2(world.bounds().minX() + random.nextDouble() * world.bounds().width(),
                    world.bounds().minZ() + random.nextDouble() * world.bounds().depth());
            double range = random.nextDouble() * 60;
            if (world.riverBeyond(at, range)) {
                beyond++;
                assertThat(world.nearestRiverPoint(at).distance()).as("at %s, range %s", at, range)
                        .isGreaterThan(range);
            }
        }
        // And it is worth having: most points of a world are far from its river.
        assertThat(beyond).isGreaterThan(trials / 4);
    }

    @Test
    void neverBeyondInTheWaterNorOutsideTheWorld() {
        World world = SmallWorld.builder().world(); // the river runs east-west over z 60..70
        assertThat(world.riverBeyond(new Point2(50, 65), 0)).isFalse();
        assertThat(world.riverBeyond(new Point2(50, 20), 5)).isTrue();
        assertThat(world.riverBeyond(new Point2(50, 20), 45)).isFalse();
        assertThat(world.riverBeyond(new Point2(-1e6, 20), 5)).isFalse();
    }
}
