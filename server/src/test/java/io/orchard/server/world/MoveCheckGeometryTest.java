package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Point2;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Geometry;

/**
 * The fast move check against the plain definition, computed with JTS's exact distances: a move
 * is free when the segment stays at least r inside the world and at least r from every trunk,
 * table, the castle and the uncovered water.
 */
class MoveCheckGeometryTest {

    private static final double TIE = 1e-6;

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {4, 5, 6})
    void randomMovesAgreeWithExactDistances(long seed) {
        World world = WorldGenerator.standard(seed).generate();
        SplittableRandom random = new SplittableRandom(seed * 31);
        int blocked = 0;
        int compared = 0;
        for (int i = 0; i < 3000; i++) {
            double ax = random.nextDouble(-101, 101);
            double az = random.nextDouble(-101, 101);
            double angle = random.nextDouble(0, 2 * Math.PI);
            double length = random.nextDouble(0, 15);
            double bx = ax + Math.cos(angle) * length;
            double bz = az + Math.sin(angle) * length;
            double r = random.nextDouble(0.2, 1.0);
            double margin = clearance(world, ax, az, bx, bz, r);
            if (Math.abs(margin) < TIE) {
                continue; // a tie between touching and overlapping: either answer is right
            }
            compared++;
            MoveResult result = world.checkMove(new Point2(ax, az), new Point2(bx, bz), r);
            assertThat(result.isFree()).as("(%s, %s) to (%s, %s) radius %s: %s", ax, az, bx, bz, r, result.reason())
                    .isEqualTo(margin > 0);
            blocked += result.isFree() ? 0 : 1;
        }
        assertThat(blocked).as("some moves are blocked").isGreaterThan(100);
        assertThat(compared - blocked).as("some moves are free").isGreaterThan(100);
    }

    /** How much room the swept disc has to spare: negative when it overlaps something. */
    private static double clearance(World world, double ax, double az, double bx, double bz, double r) {
        double room = Double.MAX_VALUE;
        var bounds = world.bounds();
        room = Math.min(room, Math.min(ax, bx) - r - bounds.minX());
        room = Math.min(room, bounds.maxX() - Math.max(ax, bx) - r);
        room = Math.min(room, Math.min(az, bz) - r - bounds.minZ());
        room = Math.min(room, bounds.maxZ() - Math.max(az, bz) - r);
        Geometry path = Shapes.path(ax, az, bx, bz);
        for (Tree tree : world.trees()) {
            room = Math.min(room, path.distance(Shapes.point(tree.position().x(), tree.position().z()))
                    - tree.trunkRadius() - r);
        }
        for (Table table : world.tables()) {
            room = Math.min(room, path.distance(Shapes.point(table.position().x(), table.position().z()))
                    - table.radius() - r);
        }
        room = Math.min(room, path.distance(world.castle().polygon()) - r);
        room = Math.min(room, path.distance(world.water().geometry()) - r);
        return room;
    }
}
