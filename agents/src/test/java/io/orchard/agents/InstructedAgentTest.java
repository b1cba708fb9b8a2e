package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.zoo.Bunny;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Role;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import io.orchard.server.world.Bridge;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.io.IOException;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Agents instructed in English, in real lockstep games of a fixed seed: the instruction is
 * grounded in what the agent sees, carried out with its behaviours and answered.
 */
class InstructedAgentTest {

    static final long SEED = 1998;

    private final World world = WorldGenerator.standard(SEED).generate();

    /** An agent with the default behaviour that notes where it stood at every tick and what it said. */
    static final class Pupil extends AgentController {
        final List<Point2> track = new CopyOnWriteArrayList<>();
        final List<Long> ticks = new CopyOnWriteArrayList<>();
        final List<String> said = new CopyOnWriteArrayList<>();

        Pupil() {
            super("Pupil");
            addSpeechListener(said::add);
        }

        @Override
        protected AgentBody body() {
            return AgentBody.builder().radius(0.4).speed(8).gripper("hands", 0.7, 0, 2)
                    .sight(35, 2 * Math.PI).build();
        }

        @Override
        protected void decide(Perception perception) {
            track.add(position());
            ticks.add(tick());
            super.decide(perception);
        }
    }

    /** A free place for the agent, as near {@code wanted} as there is one. */
    private Point2 freeNear(Point2 wanted) {
        for (int ring = 0; ring < 20; ring++) {
            for (int k = 0; k < Math.max(1, ring * 8); k++) {
                double angle = k * 2 * Math.PI / Math.max(1, ring * 8);
                Point2 p = new Point2(wanted.x() + ring * Math.cos(angle), wanted.z() + ring * Math.sin(angle));
                if (world.checkPlace(p, 1.2).isFree() && !world.river().contains(p)) {
                    return p;
                }
            }
        }
        throw new IllegalStateException("no free place near " + wanted + " in the world of seed " + SEED);
    }

    @Test
    void pickUpTheCoconutOnTheTableCollectsACoconutThatWasOnATable() throws Exception {
        Map<String, FruitState> fruit = new HashMap<>();
        Games.fruitOf(SEED).forEach(f -> fruit.put(f.id(), f));
        FruitState onTable = fruit.values().stream()
                .filter(f -> f.kind() == FruitKind.COCONUT && f.support() != null && f.support().startsWith("D"))
                .findFirst().orElseThrow(() -> new AssertionError("the world of the seed has no coconut on a table"));
        Pupil pupil = new Pupil();
        List<String> eaten = new CopyOnWriteArrayList<>();
        GameListener listener = new GameListener() {
            @Override
            public void fruitEaten(String agent, String fruitId, FruitKind kind, double time) {
                if (agent.equals("Pupil")) {
                    eaten.add(fruitId);
                }
            }
        };
        pupil.instruct("pick up the coconut on the table");

        // start nearer a coconut on the ground, so that only the words "on the table" send it to the table
        Point2 table = onTable.position().onGround();
        FruitState onGround = fruit.values().stream()
                .filter(f -> f.kind() == FruitKind.COCONUT && f.support() == null)
                .min(Comparator.comparingDouble(f -> f.position().onGround().distance(table))).orElseThrow();
        Point2 ground = onGround.position().onGround();
        double apart = ground.distance(table);
        Point2 start = freeNear(new Point2(ground.x() + (table.x() - ground.x()) / apart * 6,
                ground.z() + (table.z() - ground.z()) / apart * 6));
        assertThat(start.distance(ground)).as("precondition: the coconut on the ground is nearer")
                .isLessThan(start.distance(table) - 10);
        Games.play(SEED, 40, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), listener);

        assertThat(pupil.said.get(0)).isEqualTo("Going to pick up a coconut that lies on a table.");
        assertThat(eaten).as("what Pupil collected; said %s", pupil.said).isNotEmpty();
        FruitState first = fruit.get(eaten.get(0));
        assertThat(first.kind()).isEqualTo(FruitKind.COCONUT);
        assertThat(first.support()).as("where the coconut was").startsWith("D");
        assertThat(pupil.said).contains("Done: I picked up the coconut " + first.id() + ". Carrying on by myself.");
    }

    @Test
    void crossTheBridgeBringsItToTheOtherBankOverTheBridgeNeverThroughTheWater() throws Exception {
        Bridge bridge = world.bridges().get(1);
        Point2 near = bridge.entryA();
        Point2 far = bridge.entryB();
        double length = near.distance(far);
        Point2 start = freeNear(new Point2(near.x() + (near.x() - far.x()) / length * 8,
                near.z() + (near.z() - far.z()) / length * 8));
        Pupil pupil = new Pupil();
        int[] saidAt = {-1};
        pupil.addSpeechListener(text -> {
            if (text.startsWith("I'm on the other side of the river") && saidAt[0] < 0) {
                saidAt[0] = pupil.track.size();
            }
        });
        pupil.instruct("cross the bridge");

        Games.play(SEED, 40, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))));

        assertThat(pupil.said.get(0)).isEqualTo("Going to cross a bridge.");
        assertThat(pupil.said).contains("I'm on the other side of the river, over the bridge " + bridge.id()
                + ". Carrying on by myself.");
        List<Point2> crossing = pupil.track.subList(0, saidAt[0]);
        assertThat(crossing).as("on the deck of %s", bridge.id()).anyMatch(bridge::covers);
        assertThat(crossing).as("in the water, off every bridge").noneMatch(p -> world.river().contains(p)
                && world.bridges().stream().noneMatch(b -> b.covers(p)));
        Point2 end = crossing.get(crossing.size() - 1);
        assertThat(world.river().contains(end)).isFalse();
        assertThat(end.distance(far)).as("from the far end of the bridge").isLessThan(6);
        assertThat(end.distance(start)).isGreaterThan(length);
    }

    @Test
    void stopStopsTheAgentWithinOneTickAndItStaysStopped() throws Exception {
        Pupil pupil = new Pupil();
        GameListener teacher = new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                if (tick == 60) {
                    pupil.instruct("stop");
                }
            }
        };

        Games.play(SEED, 8, List.of(pupil), (name, radius) -> null, teacher);

        Map<Long, Point2> at = new HashMap<>();
        for (int i = 0; i < pupil.ticks.size(); i++) {
            at.put(pupil.ticks.get(i), pupil.track.get(i));
        }
        assertThat(at.get(60L).distance(at.get(40L))).as("walking before it was told to stop").isGreaterThan(1);
        for (long tick = 62; tick < 160; tick++) {
            assertThat(at.get(tick)).as("where it stood at tick %d", tick).isEqualTo(at.get(62L));
        }
        assertThat(pupil.said).contains("Stopping.");
    }

    @Test
    void anAmbiguousTreeIsAskedAboutAndTheAnswerResolvesIt() throws Exception {
        Pupil pupil = new Pupil();
        pupil.instruct("go to the tree");
        List<String> heard = new CopyOnWriteArrayList<>();
        Pattern choice = Pattern.compile("2: [^(]*\\((T\\d+)\\)");
        String[] meant = {null};
        List<Obstacle> trees = WorldGenerator.standard(SEED).scenario().trees();
        Point2 between = trees.stream().flatMap(a -> trees.stream().filter(b -> a != b
                        && a.position().distance(b.position()) < 15).map(b -> new Point2(
                        (a.position().x() + b.position().x()) / 2, (a.position().z() + b.position().z()) / 2)))
                .findFirst().orElseThrow(() -> new AssertionError("no two trees stand close in the world of the seed"));
        Point2 start = freeNear(between);
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP).timeLimit(60)
                .placement(Games.at(Map.of("Pupil", start.at(0)))).start()) {
            ProtocolConnection[] viewer = new ProtocolConnection[1];
            viewer[0] = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "teacher", message -> {
                if (message instanceof SayMessage say && say.agent().equals("Pupil")) {
                    heard.add(say.text());
                    Matcher m = choice.matcher(say.text());
                    if (say.text().startsWith("Which tree do you mean?") && m.find() && meant[0] == null) {
                        meant[0] = m.group(1);
                        try {
                            viewer[0].send(seq -> new InstructionMessage(seq, "Pupil", "the second one", "teacher"));
                        } catch (IOException e) {
                            throw new IllegalStateException(e);
                        }
                    }
                }
            });
            try (ProtocolConnection open = viewer[0]) {
                CompletableFuture<GameOverMessage> playing = CompletableFuture.supplyAsync(() -> {
                    try {
                        return pupil.run("127.0.0.1", server.port());
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                });
                playing.get(120, TimeUnit.SECONDS);
            }
        }

        assertThat(heard).as("what the viewer heard").isNotEmpty();
        assertThat(heard.get(0)).startsWith("Which tree do you mean? 1: the near");
        assertThat(meant[0]).isNotNull();
        assertThat(heard.get(1)).isEqualTo("All right, the tree " + meant[0] + ".");
        assertThat(heard.get(2)).isEqualTo("I'm at the tree " + meant[0] + ". Carrying on by myself.");
    }

    @Test
    void aBunnyAskedForACoconutInATreeSaysWhyItCannotAndDoesNotTry() throws Exception {
        Bunny bunny = new Bunny();
        List<String> said = new CopyOnWriteArrayList<>();
        bunny.addSpeechListener(said::add);
        bunny.instruct("Bunny, pick up the coconut in the tree");

        Games.play(SEED, 5, List.of(bunny));

        assertThat(said).containsExactly("I can't pick up a coconut that hangs in a tree: fruit that hangs in a tree"
                + " is 1.50 to 3.00 high, and my mouth reaches only from 0.00 to 0.50.");
    }

    @Test
    void aSentenceItCannotUnderstandIsAnsweredHelpfully() throws Exception {
        Pupil pupil = new Pupil();
        pupil.instruct("jump over the moon");
        pupil.instruct("Guppy, stop");

        Games.play(SEED, 3, List.of(pupil));

        Interpretation heard = new InstructionInterpreter().interpret("jump over the moon");
        assertThat(pupil.said).containsExactly(((Interpretation.NotUnderstood) heard).answer(),
                "That was for Guppy, not for me.");
        assertThat(pupil.said.get(0)).contains("'jump over the moon'", "'jump'", "'moon'");
        assertThat(pupil.stats().movesSent()).as("it went on with its own business").isPositive();
    }
}
