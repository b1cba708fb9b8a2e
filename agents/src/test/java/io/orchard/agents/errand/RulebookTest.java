package io.orchard.agents.errand;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.errand.ErrandsTest.Recorder;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.Views;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sight;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Rules driven without a server: what the memory's conduct forbids once a rule is taken on, what the
 * planner and the harvester make of it, what lifting lifts, and what the agent says.
 */
class RulebookTest {

    private static final Sight SIGHT = new Sight(60, 2 * Math.PI);
    private static final Body HANDS = new Body(0.4, 1.5, 8, new Gripper("hands", 0.7, 0, 2), SIGHT);

    private final WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), 0.4, SIGHT);
    private final InstructionInterpreter interpreter = new InstructionInterpreter();
    private final Recorder motor = new Recorder(HANDS);

    /** An agent at the origin, a river running east-west 30 units to the north (z -30), a tree, fruit. */
    private Errands errands() {
        memory.placed(motor.position, motor.heading);
        Views.from(0, 0, 0).tree("T1", 20, 10, 2).river(0, -30, Math.PI / 2)
                .fruit("F1", FruitKind.COCONUT, 5, 0.2, 5).fruit("F2", FruitKind.BANANA, -5, 0.2, 5)
                .fruit("F3", FruitKind.TOMATO, 0, 0.2, -34).into(memory);
        return new Errands(memory, motor);
    }

    private void tell(Errands errands, String sentence) {
        Interpretation heard = interpreter.interpret(sentence, errands.discourse());
        errands.take(((Interpretation.Understood) heard).goal());
    }

    private KnownFruit fruit(String id) {
        return memory.fruit(id).orElseThrow();
    }

    @Test
    void anAreaRuleKeepsThePlannerAndTheExplorerOutAndIsNamedWhenItRefusesAWalk() {
        Errands errands = errands();
        PathPlanner planner = new PathPlanner(memory);
        assertThat(planner.plan(new Point2(0, 0), new Point2(0, -24))).as("before the rule").isPresent();

        tell(errands, "don't go near the river");

        assertThat(motor.said).containsExactly("From now on I won't go near the river.");
        assertThat(memory.conduct().forbids(new Point2(0, -25))).isTrue();
        assertThat(memory.conduct().forbids(new Point2(0, -15))).isFalse();
        assertThat(planner.plan(new Point2(0, 0), new Point2(0, -24))).as("into the area").isEmpty();
        assertThat(planner.plan(new Point2(0, 0), new Point2(30, -12))).as("around it").isPresent();
        assertThat(memory.coverage().unseen()).as("cells to explore").noneMatch(memory.conduct()::forbids);
        assertThat(memory.conduct().cut(new Point2(0, 0), new Point2(0, -30)).z()).as("the motor's guard stops at")
                .isBetween(-20.5, -19.0);
        assertThat(errands.step()).isFalse();

        tell(errands, "go north 25 metres");

        assertThat(motor.said.get(motor.said.size() - 1)).isEqualTo("That point is against your rule not to go near "
                + "the river; the nearest place I can stand that way is 19 metres north, and I'll go there.");
    }

    @Test
    void fruitRulesLeaveTheHarvesterOnlyWhatTheyAllowAndRefuseAnErrandForTheRest() {
        Errands errands = errands();

        tell(errands, "leave the coconuts");
        tell(errands, "only bananas from now on");

        assertThat(memory.conduct().allows(fruit("F1"))).isFalse();
        assertThat(memory.conduct().allows(fruit("F2"))).isTrue();
        assertThat(memory.conduct().ruleAgainst(fruit("F3"))).contains("your rule to collect only bananas");
        assertThat(errands.harvester().candidates(f -> true)).extracting(KnownFruit::id).containsExactly("F2");

        tell(errands, "pick up a coconut");

        assertThat(motor.said.get(motor.said.size() - 1)).isEqualTo("I won't: that is against your rule to leave the "
                + "coconuts alone. Say 'forget the rules' to lift your rules.");
    }

    @Test
    void liftingLiftsWhatTheWordsAreAboutAndSaysWhatElseItLifted() {
        Errands errands = errands();
        tell(errands, "only bananas from now on");
        tell(errands, "don't go near the river");
        tell(errands, "stay on this side of the river");
        motor.said.clear();

        tell(errands, "you may take coconuts again");
        tell(errands, "you can go near the river again");
        tell(errands, "what are your rules?");
        tell(errands, "you can go to the castle again");
        tell(errands, "forget the rules");
        tell(errands, "forget the rules");

        assertThat(motor.said).containsExactly(
                "All right: I may take coconuts again; that lifts your rule to collect only bananas.",
                "All right: I may go near the river again.",
                "My rules: I stay on this side of the river. Say 'forget the rules' to lift them.",
                "I had no rule against that; I keep to the rules I have.",
                "All right: I've forgotten all my rules.",
                "I have no rules to forget; I do as I see fit.");
        assertThat(errands.rules()).isEmpty();
        assertThat(memory.conduct().restrictsPlaces()).isFalse();
    }

    @Test
    void aRuleGivenDuringAnErrandLeavesTheErrandGoing() {
        Errands errands = errands();
        tell(errands, "go to the tree");
        errands.step();
        Goal before = errands.goal();

        tell(errands, "leave the coconuts");

        assertThat(errands.goal()).isEqualTo(before).isNotNull();
        assertThat(motor.said).endsWith("From now on I'll leave the coconuts alone.");
    }

    @Test
    void anAgentToldToAvoidWhereItStandsLeavesFirst() {
        Errands errands = errands();
        Views.from(0, 0, 0).tree("T2", 4, -3, 2).into(memory);
        tell(errands, "stay away from the trees");

        errands.step();

        assertThat(motor.said).containsExactly("From now on I won't go near a tree. I'm standing where it keeps me out "
                + "of, so I'll leave first.", "I'm where your rule not to go near a tree keeps me out of; I'm leaving.");
        assertThat(motor.moves).isNotEmpty();
        assertThat(memory.conduct().forbids(motor.moves.get(motor.moves.size() - 1))).isFalse();
    }

    @Test
    void aConditionIsActedOnForTheThingSeenAndOnlyOnce() {
        Errands errands = errands();
        tell(errands, "when you see a banana, take it");
        motor.said.clear();

        errands.step();
        List<String> first = List.copyOf(motor.said);
        errands.take(((Interpretation.Understood) interpreter.interpret("stop")).goal());
        errands.take(((Interpretation.Understood) interpreter.interpret("carry on")).goal());
        motor.said.clear();
        errands.step();

        assertThat(first).containsExactly("I see the banana F2, so as you told me:",
                "Going to pick up the banana F2.");
        assertThat(motor.said).as("seen again, acted on already").isEmpty();
    }
}
