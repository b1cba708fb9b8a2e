package io.orchard.agents.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.map.Circle;
import io.orchard.agents.map.Views;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Sight;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

class PathPlannerTest {

    private static final double RADIUS = 0.4;
    private static final double EAST = -Math.PI / 2;

    private final WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), RADIUS,
            new Sight(40, 2 * Math.PI));
    private final PathPlanner planner = new PathPlanner(memory);

    /** Every point of the walk from {@code from} along {@code path}, a tenth of a unit apart. */
    private static List<Point2> walk(Point2 from, List<Point2> path) {
        List<Point2> points = new ArrayList<>();
        Point2 at = from;
        for (Point2 next : path) {
            int steps = (int) Math.ceil(at.distance(next) / 0.1);
            for (int s = 0; s <= steps; s++) {
                double f = steps == 0 ? 1 : (double) s / steps;
                points.add(new Point2(at.x() + (next.x() - at.x()) * f, at.z() + (next.z() - at.z()) * f));
            }
            at = next;
        }
        return points;
    }

    @Test
    void aClearWayIsOneStraightStretch() {
        Views.from(0, 0, 0).into(memory);

        assertThat(planner.plan(new Point2(0, 0), new Point2(20, -30))).contains(List.of(new Point2(20, -30)));
    }

    @Test
    void aPathGoesAroundATreeWithRoomToSpare() {
        Views.from(0, 0, 0).tree("T1", 0, -5, 2).into(memory);
        Point2 from = new Point2(0, 0);
        Point2 to = new Point2(0, -10);

        List<Point2> path = planner.plan(from, to).orElseThrow();

        assertThat(path).hasSizeGreaterThan(1).last().isEqualTo(to);
        double trunk = 0.3;
        assertThat(walk(from, path)).allSatisfy(p ->
                assertThat(p.distance(new Point2(0, -5))).isGreaterThanOrEqualTo(trunk + RADIUS + PathPlanner.MARGIN - 1e-6));
    }

    @Test
    void aPathGoesAroundATableAndBetweenTreesWhereThereIsRoom() {
        // Two trunks 2.2 apart leave a gap of 1.6 for a body 0.8 wide; a table blocks the way round to the left.
        Views.from(0, 0, 0).tree("T1", -1.1, -6, 2).tree("T2", 1.1, -6, 2).table("D1", -4, -6, 1, 0.8).into(memory);
        Point2 from = new Point2(0, 0);

        List<Point2> path = planner.plan(from, new Point2(0, -12)).orElseThrow();

        assertThat(walk(from, path)).allSatisfy(p -> {
            assertThat(p.distance(new Point2(-1.1, -6))).isGreaterThanOrEqualTo(0.3 + RADIUS);
            assertThat(p.distance(new Point2(1.1, -6))).isGreaterThanOrEqualTo(0.3 + RADIUS);
            assertThat(p.distance(new Point2(-4, -6))).isGreaterThanOrEqualTo(1 + RADIUS);
        });
        assertThat(PathPlanner.length(from, path)).isLessThan(13); // through the gap, not round the grove
    }

    @Test
    void otherAgentsAreKeptClearOfWhenGiven() {
        Views.from(0, 0, 0).into(memory);
        Point2 from = new Point2(0, 0);
        Circle bunny = new Circle(0, -5, 0.35);

        List<Point2> path = planner.plan(from, new Point2(0, -10), List.of(bunny)).orElseThrow();

        assertThat(walk(from, path)).allSatisfy(p ->
                assertThat(p.distance(bunny.centre())).isGreaterThanOrEqualTo(0.35 + RADIUS));
    }

    @Nested
    class TheRiver {

        /** A river from the west edge to the east edge between z = 10 and z = 20, both banks seen all along. */
        private void seeTheRiver() {
            for (double x = -95; x <= 95; x += 10) {
                Views.from(x, 0, 0).river(x, 10, EAST).into(memory);
                Views.from(x, 30, Math.PI).river(x, 20, EAST).into(memory);
            }
        }

        @Test
        void withoutABridgeThereIsNoWayAcross() {
            seeTheRiver();

            assertThat(planner.plan(new Point2(0, 0), new Point2(0, 35))).isEmpty();
            assertThat(planner.clear(new Point2(0, 0), new Point2(0, 35))).isFalse();
        }

        @Test
        void theWayAcrossLeadsOverTheBridgeAndNeverThroughTheWater() {
            seeTheRiver();
            Views.from(30, 0, 0).bridge("B1", 30, 8, 30, 22, 4).into(memory);
            Point2 from = new Point2(0, 0);

            Optional<List<Point2>> path = planner.plan(from, new Point2(0, 35));

            assertThat(path).isPresent();
            assertThat(walk(from, path.get())).allSatisfy(p -> {
                boolean overWater = p.z() > 10 - RADIUS && p.z() < 20 + RADIUS;
                if (overWater) {
                    assertThat(Math.abs(p.x() - 30)).as("over the water at %s, off the deck", p).isLessThanOrEqualTo(2 - RADIUS);
                }
            });
            assertThat(path.get().get(path.get().size() - 1)).isEqualTo(new Point2(0, 35));
        }

        @Test
        void aFarBridgeIsWorthTheDetour() {
            seeTheRiver();
            Views.from(80, 0, 0).bridge("B2", 80, 8, 80, 22, 4).into(memory);

            List<Point2> path = planner.plan(new Point2(0, 0), new Point2(0, 35)).orElseThrow();

            assertThat(PathPlanner.length(new Point2(0, 0), path)).isGreaterThan(160);
        }
    }

    @Test
    void aWayARejectedMoveTaughtIsAvoided() {
        Views.from(0, 0, 0).into(memory);
        memory.moveRejected(new Point2(0, 0), new Point2(0, -8), "path crosses tree T99");

        assertThat(planner.clear(new Point2(0, 0), new Point2(0, -12))).isFalse();
        List<Point2> path = planner.plan(new Point2(0, 0), new Point2(0, -12)).orElseThrow();
        assertThat(walk(new Point2(0, 0), path)).filteredOn(p -> p.distance(new Point2(0, 0)) > 1 && p.z() > -8)
                .allSatisfy(p -> assertThat(Math.abs(p.x())).isGreaterThan(RADIUS));
    }

    @Test
    void aMoveTheCastleRefusedLeavesAWayOutFromWhereTheAgentStands() {
        for (int k = 0; k < 16; k++) { // the castle's centre at (0, 0), located from places around it
            double angle = k * Math.PI / 8;
            see(new Point2(20 * Math.sin(angle), 20 * Math.cos(angle)));
        }
        assertThat(memory.castle().located()).as("spread %s", memory.castle().spread()).isTrue();
        for (double z = 25; z >= 11; z -= 0.5) { // it walks up to the castle, seeing as it goes
            see(new Point2(3, z));
        }
        Point2 here = new Point2(3, 11);

        memory.moveRejected(here, new Point2(10, 8), "path enters the castle");

        assertThat(planner.plan(here, new Point2(3, 25))).as("back the way it came").isPresent();
        assertThat(planner.plan(here, new Point2(25, 0))).as("around the castle").isPresent();
    }

    /** A view from {@code at} with the castle's sector as seen from there, the castle standing at (0, 0). */
    private void see(Point2 at) {
        double compass = Math.toDegrees(Math.atan2(-at.x(), at.z()));
        Views.from(at.x(), at.z(), 0).castle(Sector.values()[Math.floorMod(Math.round(compass / 45), 8)]).into(memory);
    }
}
