package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Vec3;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ReachTest {

    /**
     * Tomato F1 on the ground at (30, 30); banana F2 hanging at 2.8 in tree T1 at (50, 30); tomato
     * F3 on table D1 at (70, 30), height 0.9.
     */
    private final World world = SmallWorld.builder()
            .tree("T1", 50, 30, 2, 6)
            .table("D1", 70, 30, 1, 0.9)
            .ground("F1", FruitKind.TOMATO, 30, 30)
            .fruit("F2", FruitKind.BANANA, 50, 2.8, 29, "T1")
            .fruit("F3", FruitKind.TOMATO, 70, 1.05, 30.8, "D1")
            .world();

    private ReachResult reach(String id, double x, double z, double headingDegrees, Body body) {
        return world.reach(Vec3.ground(x, z), Math.toRadians(headingDegrees), body, world.fruit(id).orElseThrow());
    }

    @Test
    void aFruitInFrontWithinReachAndHeightCanBeGrasped() {
        // Facing north (-z), one unit south of the tomato: reach is 0.4 + 0.5 + 0.15 = 1.05.
        ReachResult result = reach("F1", 30, 31, 0, SmallWorld.SHORT);

        assertThat(result.reachable()).isTrue();
        assertThat(result.reason()).isEqualTo("fruit F1 is within reach");
    }

    @Nested
    class Distance {

        @Test
        void aFruitTooFarAwayIsRefusedWithBothDistances() {
            ReachResult result = reach("F1", 30, 32.4, 0, SmallWorld.SHORT);

            assertThat(result.reachable()).isFalse();
            assertThat(result.reason()).isEqualTo("fruit F1 is 2.4 units away, reach is 1.05");
        }

        @ParameterizedTest(name = "at distance {0}: {1}")
        @CsvSource(textBlock = """
                1.05, true
                1.06, false
                0.0,  true
                """)
        void theReachIsBodyRadiusPlusGripperReachPlusFruitRadius(double distance, boolean reachable) {
            assertThat(reach("F1", 30, 30 + distance, 0, SmallWorld.SHORT).reachable()).isEqualTo(reachable);
        }
    }

    @Nested
    class Angle {

        @ParameterizedTest(name = "heading {0} degrees: {1}")
        @CsvSource(delimiter = '|', textBlock = """
                0    | fruit F1 is within reach
                60   | fruit F1 is within reach
                -60  | fruit F1 is within reach
                61   | fruit F1 is 61° to the right of the heading, grasp angle is ±60°
                -61  | fruit F1 is 61° to the left of the heading, grasp angle is ±60°
                180  | fruit F1 is 180° to the left of the heading, grasp angle is ±60°
                """)
        void onlyAFruitWithinSixtyDegreesOfTheHeadingCanBeGrasped(double heading, String reason) {
            // The fruit is due north of the agent; turning left (positive) puts it to the right.
            assertThat(reach("F1", 30, 31, heading, SmallWorld.SHORT).reason()).isEqualTo(reason);
        }

        @Test
        void aFruitToTheWestIsToTheLeftOfANorthFacingAgent() {
            assertThat(reach("F1", 31, 30, 0, SmallWorld.SHORT).reason())
                    .isEqualTo("fruit F1 is 90° to the left of the heading, grasp angle is ±60°");
            assertThat(reach("F1", 31, 30, 90, SmallWorld.SHORT).reachable()).isTrue();
        }

        @Test
        void theGraspAngleIsDocumented() {
            assertThat(Reach.HALF_ANGLE_DEGREES).isEqualTo(60);
        }
    }

    @Nested
    class Height {

        @Test
        void aFruitHangingAboveTheGripperIsRefusedWithTheHeights() {
            ReachResult result = reach("F2", 50, 28.1, 180, SmallWorld.SHORT);

            assertThat(result.reason()).isEqualTo("fruit F2 hangs at 2.8, gripper reaches 0.0–0.6");
        }

        @Test
        void aTallAgentReachesTheSameFruit() {
            // Standing outside the trunk (radius 0.3) on the fruit's side, facing south towards it.
            assertThat(world.checkPlace(new Vec3(50, 0, 28.1).onGround(), 0.5).isFree()).isTrue();
            assertThat(reach("F2", 50, 28.1, 180, SmallWorld.TALL).reachable()).isTrue();
        }

        @Test
        void aFruitOnATableLiesAtTheTablesHeightPlusItsRadius() {
            assertThat(reach("F3", 70, 31.6, 0, SmallWorld.SHORT).reason())
                    .isEqualTo("fruit F3 lies at 1.05, gripper reaches 0.0–0.6");
            assertThat(reach("F3", 70, 31.6, 0, SmallWorld.MEDIUM).reachable()).isTrue();
        }

        @Test
        void aFruitBelowTheGripperIsRefused() {
            Body high = SmallWorld.body(0.5, 0.5, 1.0, 3.0);

            assertThat(reach("F1", 30, 31, 0, high).reason()).isEqualTo("fruit F1 lies at 0.15, gripper reaches 1.0–3.0");
        }

        @Test
        void heightIsCheckedBeforeDistance() {
            assertThat(reach("F2", 10, 50, 0, SmallWorld.SHORT).reason()).startsWith("fruit F2 hangs at 2.8");
        }
    }
}
