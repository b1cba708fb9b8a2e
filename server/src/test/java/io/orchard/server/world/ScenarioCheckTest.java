package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.scenario.ScenarioException;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Every rule a scenario's things must satisfy, one bad world per rule, refused with its message. */
class ScenarioCheckTest {

    private static Arguments refused(String message, UnaryOperator<SmallWorld> change) {
        return Arguments.of(message, change);
    }

    private static Point2 p(double x, double z) {
        return new Point2(x, z);
    }

    static Stream<Arguments> badWorlds() {
        return Stream.of(
                // overlapping things
                refused("tree T1 overlaps tree T2", w -> w.tree("T1", 40, 40, 2, 6).tree("T2", 40.5, 40, 2, 6)),
                refused("tree T3 overlaps table D1", w -> w.tree("T3", 40, 40, 2, 6).table("D1", 41, 40, 1, 0.9)),
                refused("table D1 overlaps table D2", w -> w.table("D1", 40, 40, 1, 0.9).table("D2", 41.9, 40, 1, 0.9)),
                refused("tree T1 overlaps the castle", w -> w.tree("T1", 20.2, 15, 2, 6)),
                refused("table D1 overlaps the river", w -> w.table("D1", 30, 59.5, 1, 0.9)),
                refused("tree T1 overlaps bridge B1", w -> w.tree("T1", 52.2, 58, 2, 6)),
                refused("the castle overlaps the river", w -> w.castle(10, 10, 55, 20, 55, 20, 65, 10, 65)),
                refused("the castle overlaps bridge B1", w -> w.castle(10, 45, 50, 55, 50, 55, 58, 45, 58)),
                refused("bridge B1 overlaps bridge B2", w -> w.bridges(
                        new BridgeShape("B1", p(50, 57), p(50, 73), 4), new BridgeShape("B2", p(52, 57), p(52, 73), 4))),
                // outside the world
                refused("tree T1 lies outside the world (x 0.0 to 100.0, z 0.0 to 100.0)", w -> w.tree("T1", 0.1, 40, 2, 6)),
                refused("table D1 lies outside the world", w -> w.table("D1", 40, 120, 1, 0.9)),
                refused("the castle lies outside the world", w -> w.castle(10, -5, 10, 5, 10, 5, 20, -5, 20)),
                refused("the river reaches outside the world", w -> w.river(-10, 60, 110, 60, 110, 70, -10, 70)),
                refused("bridge B1 reaches outside the world", w -> w.river(0, 90, 100, 90, 100, 98, 0, 98)
                        .bridges(new BridgeShape("B1", p(50, 88), p(50, 102), 4))),
                refused("fruit F1 lies outside the world", w -> w.ground("F1", FruitKind.TOMATO, 101, 40)),
                // the river and its bridges
                refused("the river has no bridge: agents could never cross it", w -> w.bridges()),
                refused("the river does not cross the world: it must divide the land into two banks, but leaves 1 piece",
                        w -> w.river(30, 60, 70, 60, 70, 70, 30, 70)
                                .bridges(new BridgeShape("B1", p(50, 57), p(50, 73), 4))),
                refused("the river does not cross the world: it must divide the land into two banks, but leaves 3 pieces",
                        w -> w.river(0, 60, 100, 60, 100, 70, 55, 70, 55, 100, 45, 100, 45, 70, 0, 70)),
                refused("bridge B1 does not span the river: both entries are on the north bank",
                        w -> w.bridges(new BridgeShape("B1", p(50, 40), p(50, 55), 4))),
                refused("bridge B1 does not span the river: entry B (50.0, 65.0) is in the river",
                        w -> w.bridges(new BridgeShape("B1", p(50, 57), p(50, 65), 4))),
                // fruit where no fruit can be
                refused("fruit F1 is inside the trunk of tree T1",
                        w -> w.tree("T1", 40, 40, 2, 6).ground("F1", FruitKind.TOMATO, 40.3, 40)),
                refused("fruit F1 is inside table D1",
                        w -> w.table("D1", 40, 40, 1, 0.9).ground("F1", FruitKind.TOMATO, 40.5, 40)),
                refused("fruit F1 is inside the castle", w -> w.ground("F1", FruitKind.COCONUT, 15, 15)),
                refused("fruit F1 is in the river", w -> w.ground("F1", FruitKind.BANANA, 30, 65)),
                refused("fruit F1 is inside the trunk of tree T1",
                        w -> w.tree("T1", 40, 40, 2, 6).fruit("F1", FruitKind.TOMATO, 40.2, 2, 40, "T1")),
                refused("fruit F1 lies on the ground, so its centre must be at height 0.15 (its radius), was 0.5",
                        w -> w.fruit("F1", FruitKind.TOMATO, 40, 0.5, 40, null)),
                refused("fruit F1 lies on table D1, so its centre must be at height 1.15 (the table's height plus the"
                        + " fruit's radius), was 1.0", w -> w.table("D1", 40, 40, 1, 0.9)
                        .fruit("F1", FruitKind.BANANA, 40, 1.0, 40, "D1")),
                refused("fruit F1 is not on table D1: it is 1.5 from the table's centre, the top's radius is 1.0",
                        w -> w.table("D1", 40, 40, 1, 0.9).fruit("F1", FruitKind.TOMATO, 41.5, 1.05, 40, "D1")),
                refused("fruit F1 is not in the crown of tree T1: it is 3.0 from the trunk, the crown's radius is 2.0",
                        w -> w.tree("T1", 40, 40, 2, 6).fruit("F1", FruitKind.TOMATO, 43, 2, 40, "T1")),
                refused("fruit F1 hangs at 7.0, above the top of tree T1 (height 6.0)",
                        w -> w.tree("T1", 40, 40, 2, 6).fruit("F1", FruitKind.TOMATO, 41, 7, 40, "T1")),
                refused("fruit F1 names support T9, which is neither a tree nor a table",
                        w -> w.fruit("F1", FruitKind.TOMATO, 40, 2, 40, "T9")),
                refused("fruit F1 overlaps fruit F2",
                        w -> w.ground("F1", FruitKind.COCONUT, 40, 40).ground("F2", FruitKind.COCONUT, 40.5, 40)),
                // ids, lists and outlines
                refused("duplicate id T1: tree T1 and table T1", w -> w.tree("T1", 40, 40, 2, 6).table("T1", 30, 30, 1, 1)),
                refused("duplicate id B1: bridge B1 and fruit B1", w -> w.ground("B1", FruitKind.TOMATO, 40, 40)),
                refused("table D9 is listed among the trees",
                        w -> w.treeListEntry(new Obstacle("D9", ObjectKind.TABLE, p(40, 40), 1, 1))),
                refused("the castle's footprint is not a valid polygon: self-intersection at (15.0, 15.0)",
                        w -> w.castle(10, 10, 10, 20, 20, 10, 20, 20, 10)),
                refused("the river's outline is not a valid polygon: self-intersection",
                        w -> w.river(0, 60, 100, 70, 100, 60, 0, 70)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badWorlds")
    void aBadWorldIsRefusedNamingTheObjectAndTheProblem(String message, UnaryOperator<SmallWorld> change) {
        SmallWorld world = change.apply(SmallWorld.builder());

        assertThatThrownBy(world::world)
                .isInstanceOf(ScenarioException.class)
                .satisfies(e -> assertThat(((ScenarioException) e).problems()).anyMatch(p -> p.startsWith(message)));
    }

    @Test
    void theHandBuiltWorldItselfIsAccepted() {
        assertThat(SmallWorld.builder().tree("T1", 40, 40, 2, 6).table("D1", 30, 30, 1, 0.9)
                .ground("F1", FruitKind.TOMATO, 45, 45).fruit("F2", FruitKind.TOMATO, 30, 1.05, 30.5, "D1")
                .fruit("F3", FruitKind.BANANA, 41, 2, 40, "T1").world().fruitCount()).isEqualTo(3);
    }

    @Test
    void touchingIsNotOverlapping() {
        // Trunks of radius 0.3 whose centres are 0.6 apart; a table touching the river's shore.
        assertThat(SmallWorld.builder().tree("T1", 40, 40, 2, 6).tree("T2", 40.6, 40, 2, 6)
                .table("D1", 30, 59, 1, 0.9).world().trees()).hasSize(2);
    }

    @Test
    void everyProblemIsReportedAtOnce() {
        SmallWorld world = SmallWorld.builder()
                .tree("T1", 40, 40, 2, 6).tree("T2", 40.5, 40, 2, 6)
                .ground("F1", FruitKind.TOMATO, 30, 65);

        assertThatThrownBy(world::world)
                .isInstanceOf(ScenarioException.class)
                .hasMessage("2 problems: tree T1 overlaps tree T2; fruit F1 is in the river");
    }

    @Test
    void aWorldOfPlusOrMinus1e308IsRefusedNamingTheFieldsBeforeAnyGeometryIsBuilt() {
        SmallWorld world = SmallWorld.builder().bounds(new Bounds(-1e308, -1e308, 1e308, 1e308));

        assertThatThrownBy(world::world)
                .isInstanceOf(ScenarioException.class)
                .hasMessage("4 problems: the bounds: bounds.minX must lie between -10000.0 and 10000.0, was -1.0E308; "
                        + "the bounds: bounds.minZ must lie between -10000.0 and 10000.0, was -1.0E308; "
                        + "the bounds: bounds.maxX must lie between -10000.0 and 10000.0, was 1.0E308; "
                        + "the bounds: bounds.maxZ must lie between -10000.0 and 10000.0, was 1.0E308");
    }

    static Stream<Arguments> hugeNumbers() {
        return Stream.of(
                refused("the castle: castle.footprint[1].z must lie between -10000.0 and 10000.0, was 20000.0",
                        w -> w.castle(10, 10, 10, 20, 20000, 20, 10)),
                refused("the castle: castle.height must be at most 1000.0, was 1.0E300",
                        w -> w.castle(1e300, 10, 10, 20, 10, 20, 20, 10, 20)),
                refused("the river: river.outline[0].x must lie between -10000.0 and 10000.0, was -1.0E9",
                        w -> w.river(-1e9, 60, 100, 60, 100, 70, 0, 70)),
                refused("bridge B1: bridges[0].width must be at most 1000.0, was 5000.0",
                        w -> w.bridges(new BridgeShape("B1", p(50, 57), p(50, 73), 5000))),
                refused("bridge B1: bridges[0].entryB.x must lie between -10000.0 and 10000.0, was 1.0E200",
                        w -> w.bridges(new BridgeShape("B1", p(50, 57), p(1e200, 73), 4))),
                refused("tree T1: trees[0].position.x must lie between -10000.0 and 10000.0, was -1.0E308",
                        w -> w.tree("T1", -1e308, 40, 2, 6)),
                refused("tree T1: trees[0].radius must be at most 1000.0, was 1.0E308", w -> w.tree("T1", 40, 40, 1e308, 6)),
                refused("table D1: tables[0].height must be at most 1000.0, was 1001.0", w -> w.table("D1", 40, 40, 1, 1001)),
                refused("fruit F1: fruit[0].position.y must lie between -10000.0 and 10000.0, was 1.0E10",
                        w -> w.fruit("F1", FruitKind.TOMATO, 40, 1e10, 40, null)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("hugeNumbers")
    void aNumberOutOfRangeIsRefusedNamingItsField(String message, UnaryOperator<SmallWorld> change) {
        assertThatThrownBy(change.apply(SmallWorld.builder())::world)
                .isInstanceOf(ScenarioException.class)
                .hasMessage(message);
    }

    @Test
    void aFruitOnABridgeOverTheRiverIsAllowed() {
        assertThat(SmallWorld.builder().ground("F1", FruitKind.TOMATO, 50, 65).world().fruitCount()).isEqualTo(1);
    }
}
