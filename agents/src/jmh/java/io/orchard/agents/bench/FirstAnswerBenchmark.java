package io.orchard.agents.bench;

import io.orchard.agents.errand.Errands;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.InstructionSets;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.language.Language;
import io.orchard.agents.map.WorldMemory;
import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * From a typed sentence to the agent's first answer, as {@code AgentController.onInstruction}
 * makes it: the grammar reads the sentence, and the errands ground the goal in a memory that has
 * seen 35 trees and tables and 12 fruit and say their one line. Each call takes the next sentence
 * of the three sets of instructions (corpus.tsv, fresh.tsv and german.tsv), so the sample is every
 * sentence; the agent speaks German too, so that each sentence is read as such an agent reads it, in
 * one language or, when the first does not understand it, in both.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class FirstAnswerBenchmark {

    private final InstructionInterpreter interpreter = new InstructionInterpreter(List.of("Pupil"), Language.GERMAN);
    private final List<String> sentences = new ArrayList<>();
    private Errands errands;
    private String said;
    private int next;

    @Setup
    public void setUp() throws IOException {
        sentences.addAll(InstructionSets.sentences());
        sentences.addAll(InstructionSets.german());
        Body body = new Body(0.4, 1.2, 6, new Gripper("hands", 0.7, 0, 2), new Sight(40, 2 * Math.PI));
        WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), body.radius(), body.sight());
        memory.perceive(perception(), null, null);
        errands = new Errands(memory, new Listening(memory, body));
    }

    @Benchmark
    public String typedSentenceToFirstAnswer() {
        String sentence = sentences.get(next);
        next = (next + 1) % sentences.size();
        said = null;
        Interpretation heard = interpreter.interpret(sentence);
        errands.speak(heard.language());
        if (heard instanceof Interpretation.Understood understood) {
            errands.take(understood.goal());
            if (said == null) {
                errands.step();
            }
        } else {
            said = ((Interpretation.NotUnderstood) heard).answer();
        }
        return said;
    }

    private static PerceptionMessage perception() {
        List<PerceivedObject> objects = new ArrayList<>();
        for (int i = 0; i < 35; i++) {
            objects.add(new PerceivedObject("T" + (100 + i), i % 5 == 0 ? ObjectKind.TABLE : ObjectKind.TREE,
                    new RelativePosition(5 + i, -1.5 + i * 0.09), 1.25, 6.5));
        }
        List<PerceivedFruit> fruit = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            fruit.add(new PerceivedFruit("F" + i, FruitKind.values()[i % 3], new Vec3(10.25 + 3 * i, 0.15, -30.5 + i),
                    0.15, null));
        }
        return new PerceptionMessage(10, "Pupil", new Vec3(0, 0, 0), 0, objects, List.of(), fruit);
    }

    /** A body that stays where it is and keeps what it is told to say. */
    private final class Listening implements Motor {
        private final WorldMemory memory;
        private final Body body;

        Listening(WorldMemory memory, Body body) {
            this.memory = memory;
            this.body = body;
        }

        @Override public Point2 position() { return memory.position(); }
        @Override public double heading() { return memory.heading(); }
        @Override public long tick() { return 10; }
        @Override public double time() { return 0.5; }
        @Override public Body body() { return body; }
        @Override public void moveTo(Point2 to, boolean face) { }
        @Override public void turnTo(double heading) { }
        @Override public void halt() { }
        @Override public boolean walking() { return false; }
        @Override public MoveStatus lastMove() { return null; }
        @Override public void grasp(String fruitId) { }
        @Override public GraspStatus lastGrasp() { return null; }
        @Override public void setJoint(String joint, Rotation rotation) { }
        @Override public void startAnimation(String timeSensor, boolean loop) { }
        @Override public void stopAnimation(String timeSensor) { }
        @Override public void play(String timeSensor, double seconds) { }
        @Override public void say(String text) {
            if (said == null) {
                said = text;
            }
        }
    }
}
