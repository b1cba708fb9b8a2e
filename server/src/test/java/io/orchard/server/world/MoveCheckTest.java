package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.value.Point2;
import io.orchard.server.world.MoveResult.Obstruction;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MoveCheckTest {

    /** Tree T1 at (50, 30) with crown 2 (trunk 0.3); table D1 at (70, 30), radius 1. */
    private final World world = SmallWorld.builder()
            .tree("T1", 50, 30, 2, 6)
            .table("D1", 70, 30, 1, 0.9)
            .world();

    private MoveResult move(double ax, double az, double bx, double bz) {
        return world.checkMove(new Point2(ax, az), new Point2(bx, bz), 0.5);
    }

    @ParameterizedTest(name = "{4}")
    @CsvSource(delimiter = '|', textBlock = """
            50 | 25 | 50  | 35 | path crosses tree T1                   | TREE   | T1
            70 | 25 | 70  | 35 | path crosses table D1                  | TABLE  | D1
            15 |  5 | 15  | 25 | path enters the castle                 | CASTLE |
            30 | 55 | 30  | 75 | path enters the river outside a bridge | RIVER  |
            95 | 50 | 101 | 50 | path leaves the world                  | EDGE   |
            """)
    void aMoveThroughAnObstacleIsBlockedAndNamesIt(double ax, double az, double bx, double bz, String reason,
                                                   Obstruction obstruction, String id) {
        MoveResult result = move(ax, az, bx, bz);

        assertThat(result.isFree()).isFalse();
        assertThat(result.reason()).isEqualTo(reason);
        assertThat(result.obstruction()).isEqualTo(obstruction);
        assertThat(result.objectId()).isEqualTo(id);
    }

    @ParameterizedTest(name = "standing at ({0}, {1}): {2}")
    @CsvSource(delimiter = '|', textBlock = """
            50.5  | 30   | position overlaps tree T1
            70    | 31.2 | position overlaps table D1
            20.3  | 15   | position overlaps the castle
            30    | 65   | position is in the river outside a bridge
            99.7  | 50   | position is outside the world
            30    | 30   | position is free
            50    | 65   | position is free
            """)
    void aPlaceCheckSaysPosition(double x, double z, String reason) {
        assertThat(world.checkPlace(new Point2(x, z), 0.5).reason()).isEqualTo(reason);
    }

    @Test
    void aFreeMovePasses() {
        MoveResult result = move(30, 30, 40, 45);

        assertThat(result.isFree()).isTrue();
        assertThat(result.obstruction()).isEqualTo(Obstruction.NONE);
        assertThat(result.reason()).isEqualTo("path is free");
        assertThat(result.travel()).isEqualTo(1);
    }

    @Test
    void aBridgeLetsAMoveCrossTheRiver() {
        assertThat(move(50, 50, 50, 80).isFree()).isTrue();
        assertThat(move(49.5, 55, 50.5, 75).isFree()).isTrue();
    }

    @Test
    void theRiverBlocksBesideTheBridge() {
        // The deck covers x 48..52; an agent of radius 0.5 along x = 51.8 hangs over the water.
        assertThat(move(51.8, 50, 51.8, 80).obstruction()).isEqualTo(Obstruction.RIVER);
        // Leaving the deck sideways in the middle of the river.
        assertThat(move(50, 65, 56, 65).reason()).isEqualTo("path enters the river outside a bridge");
        // Crossing diagonally: on the deck at first, over the water later.
        assertThat(move(49, 56, 56, 74).obstruction()).isEqualTo(Obstruction.RIVER);
    }

    @Test
    void theWorldsEdgeBlocksEvenWhenTheCentreStaysInside() {
        assertThat(move(50, 50, 99.6, 50).reason()).isEqualTo("path leaves the world");
        assertThat(move(50, 50, 99.5, 50).isFree()).isTrue();
        assertThat(move(50, 0.4, 60, 0.4).obstruction()).isEqualTo(Obstruction.EDGE);
    }

    @Test
    void touchingATrunkIsAllowed() {
        // The trunk's radius is 0.3 and the agent's 0.5: passing 0.8 from the trunk's centre touches it.
        assertThat(move(50.8, 25, 50.8, 35).isFree()).isTrue();
        assertThat(move(50.79, 25, 50.79, 35).obstruction()).isEqualTo(Obstruction.TREE);
    }

    @Test
    void theCrownDoesNotBlock() {
        // Within the crown (radius 2) but clear of the trunk.
        assertThat(move(51.5, 25, 51.5, 35).isFree()).isTrue();
    }

    @Test
    void whenSeveralThingsAreInTheWayTheFirstOneMetIsNamed() {
        MoveResult westward = move(80, 30, 40, 30);
        MoveResult eastward = move(40, 30, 80, 30);

        assertThat(westward.reason()).isEqualTo("path crosses table D1");
        assertThat(eastward.reason()).isEqualTo("path crosses tree T1");
    }

    @Test
    void theTravelFractionTellsHowFarTheAgentGetsBeforeTouching() {
        // The table's edge plus the agent's radius is 1.5 from its centre: contact at x = 71.5.
        assertThat(move(80, 30, 40, 30).travel()).isCloseTo((80 - 71.5) / 40, within(1e-9));
        // The river's shore is at z = 60; the agent touches it at z = 59.5, within 1/1024 of the path.
        assertThat(move(30, 50, 30, 70).travel()).isCloseTo(9.5 / 20, within(1.0 / 1024));
        assertThat(move(30, 50, 30, 70).travel()).isLessThanOrEqualTo(9.5 / 20);
        // Already overlapping at the start.
        assertThat(move(50.5, 30, 60, 30).travel()).isZero();
    }

    @Test
    void aMoveThatStartsInsideAnObstacleIsBlocked() {
        assertThat(move(15, 15, 15, 30).obstruction()).isEqualTo(Obstruction.CASTLE);
    }

    @Test
    void aMoveThatPassesAroundTheCastleIsFree() {
        assertThat(move(5, 5, 5, 30).isFree()).isTrue();
        assertThat(move(5, 9.5, 25, 9.5).isFree()).isTrue();
        assertThat(move(5, 9.6, 25, 9.6).obstruction()).isEqualTo(Obstruction.CASTLE);
    }

    @Test
    void aBadRadiusIsRefused() {
        assertThatThrownBy(() -> world.checkMove(new Point2(1, 1), new Point2(2, 2), 0))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("radius must be greater than 0, was 0.0");
    }
}
