package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SightAndLandmarksTest {

    /** The castle is the square x 10..20, z 10..20; the river runs east-west over z 60..70. */
    private final World world = SmallWorld.builder().world();

    private static Point2 p(double x, double z) {
        return new Point2(x, z);
    }

    @Nested
    class LineOfSight {

        @Test
        void theCastleHidesWhatIsBehindIt() {
            assertThat(world.lineOfSight(p(5, 15), p(25, 15))).isFalse();
            assertThat(world.castleHides(p(5, 15), p(25, 15))).isTrue();
            assertThat(world.lineOfSight(p(15, 5), p(15, 40))).isFalse();
        }

        @Test
        void aSightLinePastTheCastleIsClear() {
            assertThat(world.lineOfSight(p(5, 5), p(25, 5))).isTrue();
            assertThat(world.lineOfSight(p(30, 30), p(90, 90))).isTrue();
        }

        @Test
        void grazingAWallOrACornerDoesNotHide() {
            assertThat(world.lineOfSight(p(5, 10), p(25, 10))).isTrue();
            assertThat(world.lineOfSight(p(5, 15), p(15, 5))).isTrue();
        }

        @Test
        void treesAndTablesDoNotHide() {
            World withTree = SmallWorld.builder().tree("T1", 50, 30, 2, 6).table("D1", 60, 30, 1, 1).world();

            assertThat(withTree.lineOfSight(p(40, 30), p(70, 30))).isTrue();
        }
    }

    @Nested
    class CastleSector {

        @ParameterizedTest(name = "seen from offset ({0}, {1}) the castle is {2}")
        @CsvSource(textBlock = """
                 0,  8, NORTH
                -8,  8, NORTH_EAST
                -8,  0, EAST
                -8, -8, SOUTH_EAST
                 0, -8, SOUTH
                 8, -8, SOUTH_WEST
                 8,  0, WEST
                 8,  8, NORTH_WEST
                """)
        void theSectorIsTheDirectionFromTheViewerToTheCastle(double dx, double dz, Sector expected) {
            // The castle's centre is (15, 15); the viewer stands at the offset from it.
            assertThat(world.castleSector(p(15 + dx, 15 + dz))).isEqualTo(expected);
        }

        @Test
        void aSectorSpansFortyFiveDegrees() {
            // 22 degrees east of north is still north; 23 degrees is north-east.
            double far = 40;
            assertThat(world.castleSector(p(15 - far * Math.sin(Math.toRadians(22)), 15 + far * Math.cos(Math.toRadians(22)))))
                    .isEqualTo(Sector.NORTH);
            assertThat(world.castleSector(p(15 - far * Math.sin(Math.toRadians(23)), 15 + far * Math.cos(Math.toRadians(23)))))
                    .isEqualTo(Sector.NORTH_EAST);
        }
    }

    @Nested
    class River {

        @Test
        void theNearestPointOfTheRiverIsOnItsShore() {
            RiverPoint fromNorth = world.nearestRiverPoint(p(30, 40));
            RiverPoint fromSouth = world.nearestRiverPoint(p(30, 90));

            assertThat(fromNorth.point()).isEqualTo(p(30, 60));
            assertThat(fromNorth.distance()).isEqualTo(20);
            assertThat(fromSouth.point()).isEqualTo(p(30, 70));
            assertThat(fromSouth.distance()).isEqualTo(20);
        }

        @Test
        void inTheRiverTheNearestPointIsTheAgentsOwn() {
            RiverPoint inside = world.nearestRiverPoint(p(30, 65));

            assertThat(inside.point()).isEqualTo(p(30, 65));
            assertThat(inside.distance()).isZero();
        }

        @Test
        void anEastWestRiverRunsAtHeadingHalfPi() {
            // West is heading +pi/2; the river runs both ways, folded into (-pi/2, pi/2].
            assertThat(world.nearestRiverPoint(p(30, 40)).heading()).isCloseTo(Math.PI / 2, within(1e-12));
        }

        @Test
        void aNorthSouthRiverRunsAtHeadingZeroAndHasWestAndEastBanks() {
            World northSouth = SmallWorld.builder()
                    .river(60, 0, 70, 0, 70, 100, 60, 100)
                    .bridges(new BridgeShape("B1", p(57, 50), p(73, 50), 4))
                    .world();

            assertThat(northSouth.nearestRiverPoint(p(30, 40)).heading()).isCloseTo(0, within(1e-12));
            assertThat(northSouth.nearestRiverPoint(p(30, 40)).point()).isEqualTo(p(60, 40));
            assertThat(northSouth.bankOf(p(30, 40))).contains(Bank.WEST);
            assertThat(northSouth.bankOf(p(90, 40))).contains(Bank.EAST);
            assertThat(northSouth.river().banks()).containsExactlyInAnyOrder(Bank.WEST, Bank.EAST);
        }

        @Test
        void aSlantedRiverRunsAlongItsShore() {
            // A band from (0, 40)-(0, 50) to (100, 90)-(100, 100): it runs 50 south for 100 east.
            World slanted = SmallWorld.builder()
                    .river(0, 40, 100, 90, 100, 100, 0, 50)
                    .bridges(new BridgeShape("B1", p(50, 60), p(46, 78), 4))
                    .castle(10, 10, 10, 20, 10, 20, 20, 10, 20)
                    .world();
            double heading = slanted.nearestRiverPoint(p(60, 30)).heading();

            // Running east-south-east: the heading of (+1, +0.5) is atan2(-1, -0.5), folded.
            assertThat(heading).isCloseTo(Math.atan2(-1, -0.5) + Math.PI, within(1e-9));
        }

        @Test
        void pointsLieOnTheNorthOrSouthBankOrInTheRiver() {
            assertThat(world.bankOf(p(30, 40))).contains(Bank.NORTH);
            assertThat(world.bankOf(p(30, 80))).contains(Bank.SOUTH);
            assertThat(world.bankOf(p(30, 65))).isEmpty();
            assertThat(world.bankOf(p(50, 65))).isEmpty();
            assertThat(world.bankOf(p(150, 40))).isEmpty();
            assertThat(world.river().banks()).containsExactlyInAnyOrder(Bank.NORTH, Bank.SOUTH);
        }

        @Test
        void aPointOnTheDeckIsOnTheBridge() {
            assertThat(world.onBridge(p(50, 65))).isTrue();
            assertThat(world.bridgeAt(p(51.9, 58))).map(Bridge::id).contains("B1");
            assertThat(world.onBridge(p(52.1, 65))).isFalse();
            assertThat(world.onBridge(p(50, 74))).isFalse();
            assertThat(world.onBridge(p(30, 65))).isFalse();
        }

        @Test
        void aBridgesDeckIsARectangleAroundItsEntries() {
            assertThat(world.bridges().get(0).deck())
                    .containsExactlyInAnyOrder(p(48, 57), p(48, 73), p(52, 73), p(52, 57));
        }
    }
}
