package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Point2;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;

/**
 * A sight line that crosses a wall is found blocked without JTS's relate; every answer must stay
 * what relate alone gives: checked on many lines around a square and a concave castle, lines
 * through corners, along walls, ending on walls and inside, as well as anywhere.
 */
class SightlineTest {

    private static boolean byRelate(Castle castle, double ax, double az, double bx, double bz) {
        Geometry line = Shapes.path(ax, az, bx, bz);
        return !(castle.prepared().intersects(line) && castle.polygon().relate(line, "T********"));
    }

    /** A point anywhere near the castle, or on one of its corners or walls, where lines graze. */
    private static double[] point(SplittableRandom random, List<Point2> corners) {
        Point2 a = corners.get(random.nextInt(corners.size()));
        Point2 b = corners.get((corners.indexOf(a) + 1) % corners.size());
        return switch (random.nextInt(4)) {
            case 0 -> new double[] {a.x(), a.z()};
            case 1 -> {
                double t = random.nextInt(5) / 4.0;
                yield new double[] {a.x() + t * (b.x() - a.x()), a.z() + t * (b.z() - a.z())};
            }
            default -> new double[] {random.nextInt(-10, 50) + (random.nextBoolean() ? 0 : random.nextDouble()),
                random.nextInt(-10, 50) + (random.nextBoolean() ? 0 : random.nextDouble())};
        };
    }

    private static void agreesWithRelate(World world) {
        Castle castle = world.castle();
        List<Point2> corners = castle.footprint();
        SplittableRandom random = new SplittableRandom(17);
        int blocked = 0;
        for (int n = 0; n < 40_000; n++) {
            double[] a = point(random, corners);
            double[] b = point(random, corners);
            boolean expected = byRelate(castle, a[0], a[1], b[0], b[1]);
            assertThat(world.lineOfSight(new Point2(a[0], a[1]), new Point2(b[0], b[1])))
                    .as("from (%s, %s) to (%s, %s)", a[0], a[1], b[0], b[1]).isEqualTo(expected);
            blocked += expected ? 0 : 1;
        }
        assertThat(blocked).as("lines the castle hides").isGreaterThan(5_000);
    }

    @Test
    void aSquareCastleHidesWhatRelateSaysItHides() {
        agreesWithRelate(SmallWorld.builder().world());
    }

    @Test
    void aConcaveCastleHidesWhatRelateSaysItHides() {
        agreesWithRelate(SmallWorld.builder().castle(10, 10, 10, 30, 10, 30, 20, 20, 20, 20, 35, 10, 35).world());
    }
}
