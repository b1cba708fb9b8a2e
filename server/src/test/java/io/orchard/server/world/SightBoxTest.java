package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SightBoxTest {

    /** Every point of the sector, edges and arc included, lies in the box. */
    @ParameterizedTest
    @ValueSource(doubles = {0.1, 1.0, 2.0, Math.PI * 2 / 3, 3.0, Math.PI, 5.0, 2 * Math.PI, 7.0})
    void holdsEveryPointOfTheSector(double field) {
        Random random = new Random(7);
        for (int trial = 0; trial < 2_000; trial++) {
            double x = random.nextDouble() * 200 - 100;
            double z = random.nextDouble() * 200 - 100;
            double range = 0.5 + random.nextDouble() * 60;
            double heading = random.nextDouble() * 4 * Math.PI - 2 * Math.PI;
            SightBox box = SightBox.of(x, z, range, heading, field);
            double half = Math.min(field / 2, Math.PI);
            for (int k = 0; k <= 64; k++) {
                double angle = heading - half + 2 * half * k / 64; // a direction within the field
                for (double depth : new double[] {0, range / 3, range}) {
                    double px = x - Math.sin(angle) * depth;
                    double pz = z - Math.cos(angle) * depth;
                    assertThat(box.contains(px, pz)).as("field %s heading %s point %s,%s", field, heading, px, pz)
                            .isTrue();
                }
            }
        }
    }

    @Test
    void aNarrowFieldFacingNorthTakesOnlyTheNorthernStrip() {
        SightBox box = SightBox.of(10, 20, 50, 0, Math.toRadians(120));
        // North is -z; the arc spans ±60° around it, so x reaches 50·sin 60° either way.
        assertThat(box.minZ()).isCloseTo(20 - 50, org.assertj.core.data.Offset.offset(1e-3));
        assertThat(box.maxZ()).isCloseTo(20, org.assertj.core.data.Offset.offset(1e-3));
        assertThat(box.minX()).isCloseTo(10 - 50 * Math.sin(Math.PI / 3), org.assertj.core.data.Offset.offset(1e-3));
        assertThat(box.maxX()).isCloseTo(10 + 50 * Math.sin(Math.PI / 3), org.assertj.core.data.Offset.offset(1e-3));
    }

    @Test
    void aFieldOfAWholeTurnIsTheSquareAroundTheCircle() {
        assertThat(SightBox.of(1, 2, 10, 0.3, 2 * Math.PI)).isEqualTo(SightBox.around(1, 2, 10));
    }

    @Test
    void facingEastReachesTheFullRangeEastOnly() {
        // Heading -π/2 faces (-sin, -cos) = (1, 0): east.
        SightBox box = SightBox.of(0, 0, 10, -Math.PI / 2, Math.toRadians(90));
        assertThat(box.maxX()).isCloseTo(10, org.assertj.core.data.Offset.offset(1e-3));
        assertThat(box.minX()).isCloseTo(0, org.assertj.core.data.Offset.offset(1e-3));
        assertThat(box.maxZ() - box.minZ()).isCloseTo(2 * 10 * Math.sin(Math.PI / 4),
                org.assertj.core.data.Offset.offset(1e-3));
    }
}
