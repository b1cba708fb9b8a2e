package io.orchard.agents.errand;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Collect;
import io.orchard.agents.language.Follow;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.GoTo;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.language.LookFor;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.Views;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Sight;
import java.util.List;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/** References grounded in a memory built by hand, as the agent's perceptions would build it. */
class GrounderTest {

    private static final InstructionInterpreter INTERPRETER = new InstructionInterpreter();
    private static final double EAST = -Math.PI / 2;

    private final WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), 0.4,
            new Sight(60, 2 * Math.PI));
    private final Grounder grounder = new Grounder(memory);

    /** The reference of the goal an instruction becomes. */
    static Reference said(String instruction) {
        Interpretation heard = INTERPRETER.interpret(instruction);
        assertThat(heard).as(instruction).isInstanceOf(Interpretation.Understood.class);
        Goal goal = ((Interpretation.Understood) heard).goal();
        if (goal instanceof Collect collect) {
            return collect.what();
        }
        if (goal instanceof GoTo goTo) {
            return goTo.destination();
        }
        if (goal instanceof Follow follow) {
            return follow.agent();
        }
        return ((LookFor) goal).what();
    }

    private List<String> fitting(String instruction) {
        return grounder.fitting(said(instruction)).stream().map(Known::id).toList();
    }

    private Grounding ground(String instruction) {
        return grounder.ground(said(instruction));
    }

    private static String chosen(Grounding grounding) {
        assertThat(grounding).isInstanceOf(Grounding.Found.class);
        return ((Grounding.Found) grounding).chosen().id();
    }

    @Nested
    class PickedOutByHeightCompassSideOrLandmark {

        /** From (0, 0) facing north: a coconut on a table to the east, one high in a tree to the west, one on the ground behind. */
        void orchard() {
            Views.from(0, 0, 0)
                    .table("D1", 10, 0, 0.8, 0.9).tree("T1", -10, 0, 2.5)
                    .fruit("F1", FruitKind.COCONUT, 10.2, 1.25, 0.1, "D1")
                    .fruit("F3", FruitKind.COCONUT, -10.5, 2.4, 0.5, "T1")
                    .fruit("F5", FruitKind.COCONUT, 3, 0.35, 4, null)
                    .into(memory);
            grounder.told(memory.position(), memory.heading());
        }

        @Test
        void theHighestAndTheLowestAreByTheHeightOfTheFruit() {
            orchard();
            assertThat(chosen(ground("grab the highest coconut"))).isEqualTo("F3");
            assertThat(chosen(ground("pick up the lowest coconut"))).isEqualTo("F5");
        }

        @Test
        void theNorthernmostAndTheSouthernmostAreByWhereTheyLie() {
            orchard();
            assertThat(chosen(ground("get the northernmost coconut"))).isEqualTo("F1");
            assertThat(chosen(ground("get the southernmost coconut"))).isEqualTo("F5");
        }

        @Test
        void closestToALandmarkIsMeasuredFromTheLandmarkNotFromTheAgent() {
            orchard();
            assertThat(chosen(ground("get the nearest coconut"))).isEqualTo("F5");
            assertThat(chosen(ground("get the coconut closest to the table"))).isEqualTo("F1");
            assertThat(chosen(ground("get the coconut farthest from the table"))).isEqualTo("F3");
        }

        @Test
        void sidesAreTakenFromTheHeadingTheAgentHadWhenTold() {
            orchard();
            assertThat(fitting("get the coconut on your left")).containsExactly("F3");
            assertThat(chosen(ground("get the coconut behind you"))).isEqualTo("F5");
            assertThat(fitting("get the coconuts in front of you")).isEmpty();
            assertThat(fitting("get the coconuts near you")).contains("F5").doesNotContain("F3");
        }
    }

    @Nested
    class FruitAndWhereItIs {

        /** From (0, 0): a table D1 with a coconut and a banana, a tree T1 with a coconut above and a tomato below. */
        void orchard() {
            Views.from(0, 0, 0)
                    .table("D1", 10, 0, 0.8, 0.9).tree("T1", -10, 0, 2.5)
                    .fruit("F1", FruitKind.COCONUT, 10.2, 1.25, 0.1, "D1")
                    .fruit("F2", FruitKind.BANANA, 9.8, 1.15, -0.2, "D1")
                    .fruit("F3", FruitKind.COCONUT, -10.5, 2.4, 0.5, "T1")
                    .fruit("F4", FruitKind.TOMATO, -9, 0.15, 1, null)
                    .fruit("F5", FruitKind.COCONUT, 3, 0.35, 4, null)
                    .fruit("F6", FruitKind.TOMATO, 30, 0.15, 30, null)
                    .into(memory);
        }

        @Test
        void theCoconutOnTheTableIsTheOneOnATableAndNoOther() {
            orchard();

            assertThat(fitting("pick up the coconut on the table")).containsExactly("F1");
            assertThat(fitting("grab the coconut from the table")).containsExactly("F1");
            assertThat(fitting("get the fruit on the table")).containsExactlyInAnyOrder("F1", "F2");
        }

        @Test
        void inTheTreeHangsAndUnderTheTreeLiesOnTheGround() {
            orchard();

            assertThat(fitting("pick up the coconut in the tree")).containsExactly("F3");
            assertThat(fitting("eat the tomato under the tree")).containsExactly("F4");
            assertThat(fitting("pick up the coconut on the ground")).containsExactly("F5");
        }

        @Test
        void theNearestAndTheFarthestAreMeasuredFromTheAgent() {
            orchard();

            assertThat(chosen(ground("get the nearest fruit"))).isEqualTo("F5");
            assertThat(chosen(ground("get the farthest tomato"))).isEqualTo("F6");
            // fruit is never asked about: any that fits will do, the nearest first
            assertThat(chosen(ground("pick up a coconut"))).isEqualTo("F5");
        }

        @Test
        void aFruitNobodyHasSeenIsUnknownAndAnUnknownAnchorFitsNothing() {
            Views.from(0, 0, 0).tree("T1", -10, 0, 2.5).fruit("F5", FruitKind.COCONUT, 3, 0.35, 4, null).into(memory);

            assertThat(ground("pick up the banana")).isInstanceOf(Grounding.Unknown.class);
            assertThat(ground("pick up the coconut on the table")).isInstanceOf(Grounding.Unknown.class);
        }

        @Test
        void fruitThatIsEatenIsForgotten() {
            orchard();
            memory.fruitEaten("F1");

            assertThat(ground("pick up the coconut on the table")).isInstanceOf(Grounding.Unknown.class);
        }
    }

    @Nested
    class TreesBySizeDistanceAndPlace {

        @Test
        void severalTreesAndNoCueAreAmbiguousNearestFirst() {
            Views.from(0, 0, 0).tree("T1", 0, -20, 1).tree("T2", 0, 10, 2).tree("T3", 30, 0, 4).into(memory);

            Grounding grounding = ground("go to the tree");

            assertThat(grounding).isInstanceOf(Grounding.Ambiguous.class);
            assertThat(((Grounding.Ambiguous) grounding).choices()).extracting(Known::id)
                    .containsExactly("T2", "T1", "T3");
        }

        @Test
        void sizesCompareATreeWithTheOthersOfItsKind() {
            Views.from(0, 0, 0).tree("T1", 0, -20, 1).tree("T2", 0, 10, 2).tree("T3", 30, 0, 4).into(memory);

            assertThat(fitting("go to the big tree")).containsExactly("T2", "T3");
            assertThat(fitting("go to the small tree")).containsExactly("T2", "T1");
            assertThat(chosen(ground("go to the largest tree"))).isEqualTo("T3");
            assertThat(chosen(ground("go to the nearest tree"))).isEqualTo("T2");
            assertThat(chosen(ground("go to the farthest tree"))).isEqualTo("T3");
        }

        @Test
        void aCompassPlaceWithoutAnAnchorIsSeenFromTheAgent() {
            Views.from(0, 0, 0).tree("T1", 0, -20, 1).tree("T2", 0, 10, 2).tree("T3", 30, 0, 4).into(memory);

            assertThat(fitting("go to the tree to the north")).containsExactly("T1");
            assertThat(fitting("go to the tree to the east")).containsExactly("T3");
        }

        @Test
        void theRiverDividesThisSideFromTheOther() {
            // the river runs east-west with its north bank at z = 10; the agent stands north of it
            Views.from(0, 0, 0).river(0, 10, EAST).tree("T1", 5, 3, 2).tree("T2", 5, 40, 2)
                    .fruit("F1", FruitKind.BANANA, -3, 0.25, 45, null).fruit("F2", FruitKind.BANANA, 2, 0.25, -8, null)
                    .into(memory);
            Views.from(20, 0, 0).river(20, 10, EAST).into(memory);

            assertThat(fitting("collect everything on the other side of the river")).containsExactly("F1");
            assertThat(fitting("pick up the banana on this side of the river")).containsExactly("F2");
            assertThat(fitting("go to the tree by the river")).containsExactly("T1");
            assertThat(fitting("go to the tree across the bridge")).containsExactly("T2");
        }

        @Test
        void nearAndNorthOfTheCastleFollowItsEstimatedCentre() {
            castleAt(new Point2(0, -60));
            Views.from(0, 0, 0).tree("T1", 6, -45, 2).tree("T2", 0, -85, 2).tree("T3", 40, 0, 2).into(memory);

            assertThat(fitting("go to the tree near the castle")).containsExactly("T1");
            assertThat(fitting("go to the tree north of the castle")).containsExactly("T2");
        }

        private void castleAt(Point2 castle) {
            for (int ring = 0; ring < 2; ring++) {
                double distance = 25 + 20 * ring;
                for (int k = 0; k < 12; k++) {
                    double angle = k * Math.PI / 6;
                    Point2 from = new Point2(castle.x() + distance * Math.cos(angle),
                            castle.z() + distance * Math.sin(angle));
                    Views.from(from.x(), from.z(), 0).castle(Sector.of(castle.x() - from.x(), castle.z() - from.z()))
                            .into(memory);
                }
            }
        }
    }

    @Nested
    class AgentsAndBridges {

        @Test
        void anAgentIsFoundByItsNameInAnyCase() {
            Views.from(0, 0, 0).agent("Roadrunner", 5, 5).agent("Bunny", -5, 5).into(memory);

            assertThat(chosen(ground("follow roadrunner"))).isEqualTo("Roadrunner");
            assertThat(ground("follow Guppy")).isInstanceOf(Grounding.Unknown.class);
        }

        @Test
        void twoBridgesAreAmbiguousUnlessTheWordsPickOne() {
            Views.from(0, 0, 0).river(0, 10, EAST).bridge("B1", -30, 10, -30, 20, 4).bridge("B2", 20, 10, 20, 20, 4)
                    .into(memory);

            assertThat(ground("go to the bridge")).isInstanceOf(Grounding.Ambiguous.class);
            assertThat(chosen(ground("go to the nearest bridge"))).isEqualTo("B2");
            assertThat(chosen(ground("go to the farthest bridge"))).isEqualTo("B1");
        }
    }
}
