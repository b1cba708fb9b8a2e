package io.orchard.agents.errand;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.map.Views;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sight;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Errands driven tick by tick without a server: what the agent says and sends for each instruction. */
class ErrandsTest {

    private static final Sight SIGHT = new Sight(60, 2 * Math.PI);
    private static final Body HANDS = new Body(0.4, 1.5, 8, new Gripper("hands", 0.7, 0, 2), SIGHT);
    private static final Body MOUTH = new Body(0.35, 0.6, 12, new Gripper("mouth", 0.3, 0, 0.5), SIGHT);

    private final WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), 0.4, SIGHT);
    private final InstructionInterpreter interpreter = new InstructionInterpreter();

    /** A motor that records what the errands do; the agent stands where the test puts it. */
    static final class Recorder implements Motor {
        final List<String> said = new ArrayList<>();
        final List<Point2> moves = new ArrayList<>();
        final List<Double> turns = new ArrayList<>();
        final Body body;
        Point2 position = new Point2(0, 0);
        double heading;
        double time;
        boolean walking;

        Recorder(Body body) {
            this.body = body;
        }

        @Override public Point2 position() { return position; }
        @Override public double heading() { return heading; }
        @Override public long tick() { return Math.round(time * 20); }
        @Override public double time() { return time; }
        @Override public Body body() { return body; }
        @Override public void moveTo(Point2 to, boolean face) { moves.add(to); walking = true; }
        @Override public void turnTo(double newHeading) { turns.add(newHeading); heading = newHeading; }
        @Override public void halt() { moves.add(position); walking = false; }
        @Override public boolean walking() { return walking; }
        @Override public MoveStatus lastMove() { return null; }
        @Override public void grasp(String fruitId) { }
        @Override public GraspStatus lastGrasp() { return null; }
        @Override public void setJoint(String joint, Rotation rotation) { }
        @Override public void startAnimation(String timeSensor, boolean loop) { }
        @Override public void stopAnimation(String timeSensor) { }
        @Override public void play(String timeSensor, double seconds) { }
        @Override public void say(String text) { said.add(text); }
    }

    private Goal goal(String instruction) {
        return ((Interpretation.Understood) interpreter.interpret(instruction)).goal();
    }

    private Errands errands(Recorder motor) {
        memory.placed(motor.position, motor.heading);
        Views.from(0, 0, 0).tree("T1", 0, -20, 2).tree("T2", 15, 0, 2)
                .fruit("F1", FruitKind.COCONUT, 0.5, 2.4, -20, "T1").into(memory);
        return new Errands(memory, motor);
    }

    @Test
    void anAmbiguousTreeIsAskedAboutTheAgentWaitsAndTheAnswerSendsItToTheOneChosen() {
        Recorder motor = new Recorder(HANDS);
        Errands errands = errands(motor);

        errands.take(goal("go to the tree"));

        assertThat(motor.said).singleElement().asString().startsWith("Which tree do you mean? 1: the nearer one");
        assertThat(errands.asking()).isTrue();
        assertThat(errands.step()).as("the question holds the agent").isTrue();
        assertThat(motor.moves).isEmpty();
        assertThat(errands.answer("banana")).isFalse();
        assertThat(errands.answer("the north one")).isTrue();
        assertThat(motor.said.get(1)).isEqualTo("All right, the tree T1.");
        assertThat(errands.asking()).isFalse();
        errands.step();
        assertThat(motor.moves).as("on its way to T1, north").singleElement()
                .satisfies(p -> assertThat(p.z()).isLessThan(-5));
    }

    @Test
    void aWalkWithADistanceEndsThatFarAwayInThatDirection() {
        Recorder motor = new Recorder(HANDS);
        Errands errands = errands(motor);
        errands.take(goal("walk 10 metres to the east"));

        assertThat(motor.said).singleElement().isEqualTo("Going 10 metres east.");
        for (int tick = 0; tick < 100 && errands.step(); tick++) {
            if (motor.walking) { // arrives at once where it was sent
                motor.position = motor.moves.get(motor.moves.size() - 1);
                motor.walking = false;
            }
            motor.time += 0.05;
        }

        assertThat(motor.said).last().isEqualTo("Done: I went 10 metres east. Carrying on by myself.");
        assertThat(motor.position.distance(new Point2(10, 0))).as("ended at %s", motor.position).isLessThan(1);
    }

    @Test
    void aNewInstructionCancelsTheQuestion() {
        Recorder motor = new Recorder(HANDS);
        Errands errands = errands(motor);
        errands.take(goal("go to the tree"));

        errands.take(goal("turn left"));

        assertThat(errands.asking()).isFalse();
        assertThat(errands.answer("the north one")).isFalse();
        assertThat(errands.step()).isTrue();
        assertThat(motor.said).last().isEqualTo("Done: I'm facing west. Carrying on by myself.");
        assertThat(errands.step()).as("back to autonomy").isFalse();
    }

    @Test
    void noAnswerInTimeTakesTheNearest() {
        Recorder motor = new Recorder(HANDS);
        Errands errands = errands(motor);
        errands.take(goal("go to the tree"));

        motor.time = Errands.ANSWER_SECONDS;
        errands.step();

        assertThat(motor.said).last().isEqualTo("No answer: I'll take the nearest, the tree T2.");
        assertThat(errands.busy()).isTrue();
    }

    @Test
    void stopHaltsAtOnceAndHoldsUntilTheNextInstruction() {
        Recorder motor = new Recorder(HANDS);
        Errands errands = errands(motor);
        motor.walking = true;

        errands.take(goal("stop"));

        assertThat(motor.said).containsExactly("Stopping.");
        assertThat(motor.moves).containsExactly(new Point2(0, 0));
        for (int tick = 0; tick < 100; tick++) {
            motor.time += 0.05;
            assertThat(errands.step()).isTrue();
        }
        assertThat(motor.moves).hasSize(1);
        errands.take(goal("carry on"));
        assertThat(motor.said).last().isEqualTo("Carrying on by myself.");
        assertThat(errands.step()).isFalse();
    }

    @Test
    void whatTheBodyCannotReachIsRefusedAndNotPursued() {
        Recorder motor = new Recorder(MOUTH);
        Errands errands = errands(motor);

        errands.take(goal("pick up the coconut in the tree"));

        assertThat(motor.said).singleElement().asString().startsWith("I can't pick up a coconut that hangs in a tree");
        assertThat(errands.busy()).isFalse();
        assertThat(errands.step()).isFalse();
    }

    @Test
    void somethingNotKnownIsSaidAndLookedFor() {
        Recorder motor = new Recorder(HANDS);
        Errands errands = errands(motor);

        errands.take(goal("pick up the banana on the table"));
        errands.step();

        assertThat(motor.said).containsExactly("Going to pick up a banana that lies on a table.",
                "I don't know of a banana that lies on a table yet; I'll look for one.");
        assertThat(motor.moves).as("exploring").isNotEmpty();
    }

    @Test
    void aSequenceGoesOnAfterAStepTheBodyCannotDo() {
        Recorder motor = new Recorder(MOUTH);
        Errands errands = errands(motor);

        errands.take(goal("pick up the coconut in the tree and then turn around"));
        errands.step();

        assertThat(motor.said.get(0)).startsWith("I can't pick up a coconut that hangs in a tree")
                .endsWith("I'll go on with the rest.");
        assertThat(motor.said.get(1)).isEqualTo("Done: I'm facing south. Carrying on by myself.");
    }
}
