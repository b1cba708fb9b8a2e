package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import io.orchard.server.sim.GameListener;
import io.orchard.server.world.Table;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The instructions a new user types, in real lockstep games of a fixed seed: questions answered
 * from the agent's own state while it goes on with its errand, the start point remembered, both
 * parts of "collect two bananas and bring them to me" done, a walk into the river cut short with
 * the reason said, a table chosen by "behind you", and another language answered in English.
 */
class QuestionsAndPlacesGameTest {

    private static final long SEED = InstructedAgentTest.SEED;

    private final World world = WorldGenerator.standard(SEED).generate();

    /** An agent with the default behaviour that notes where it stood, which way it faced and what it said. */
    static final class Listener extends AgentController {
        final List<Point2> track = new CopyOnWriteArrayList<>();
        final List<Double> headings = new CopyOnWriteArrayList<>();
        final List<String> said = new CopyOnWriteArrayList<>();
        /** For each line said, how many ticks it had noted by then. */
        final List<Integer> saidAt = new CopyOnWriteArrayList<>();

        Listener() {
            super("Pupil");
            addSpeechListener(text -> {
                said.add(text);
                saidAt.add(track.size());
            });
        }

        /** Where it stood when it said the first line that starts with {@code prefix}. */
        Point2 whereItSaid(String prefix) {
            for (int i = 0; i < said.size(); i++) {
                if (said.get(i).startsWith(prefix)) {
                    return track.get(Math.max(0, saidAt.get(i) - 1));
                }
            }
            throw new AssertionError("never said '" + prefix + "...'; said " + said);
        }

        @Override
        protected AgentBody body() {
            return AgentBody.builder().radius(0.4).speed(8).gripper("hands", 0.7, 0, 2)
                    .sight(35, 2 * Math.PI).build();
        }

        @Override
        protected void decide(Perception perception) {
            track.add(position());
            headings.add(heading());
            super.decide(perception);
        }

        /** What it said after it had said {@code earlier}, the first line that matches. */
        String after(String earlier, Pattern pattern) {
            int from = said.indexOf(earlier);
            return said.subList(Math.max(0, from), said.size()).stream().filter(s -> pattern.matcher(s).find())
                    .findFirst().orElse(null);
        }
    }

    /** A listener of the game that gives the agent a sentence at each tick of the script. */
    private static GameListener script(AgentController agent, Map<Long, String> lines) {
        return new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                String line = lines.get(tick);
                if (line != null) {
                    agent.instruct(line);
                }
            }
        };
    }

    @Test
    void questionsAreAnsweredFromTheAgentsOwnStateWhileItGoesOnWithItsErrand() throws Exception {
        Listener pupil = new Listener();
        Point2 start = Games.freeWalk(SEED, 12)[0];
        pupil.instruct("where are you?");
        GameListener teacher = script(pupil, Map.of(
                4L, "which way are you facing?",
                8L, "how many fruits have you got?",
                12L, "what are you doing?",
                16L, "pick up the nearest banana",
                20L, "what are you doing and why?",
                24L, "what do you see?",
                28L, "where is the nearest banana?",
                560L, "how many bananas have you collected?",
                564L, "stop",
                568L, "why did you stop?"));

        Games.play(SEED, 30, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), teacher);

        List<String> said = pupil.said;
        assertThat(said.get(0)).as("said %s", said).startsWith("I'm ").doesNotContain("Going");
        assertThat(said).as("said").contains("I'm facing " + compass(pupil.headings.get(0)) + ".");
        assertThat(said).contains("I haven't collected any fruit yet.",
                "Nothing you asked: I'm on my own, looking for fruit to collect, because that is what I do when no "
                        + "one tells me otherwise.",
                "Going to pick up the nearest banana.",
                "I'm going to pick up the nearest banana, because you asked me to.");
        assertThat(pupil.after("Going to pick up the nearest banana.", Pattern.compile("^I see ")))
                .as("said %s", said).isNotNull();
        assertThat(pupil.after("Going to pick up the nearest banana.", Pattern.compile("^(The banana|I know of)")))
                .as("said %s", said).isNotNull();
        assertThat(said).as("the questions did not stop the errand").anyMatch(s -> s.startsWith("Done: I picked up "
                + "the banana"));
        assertThat(said).contains("I have collected a banana.", "Stopping.",
                "You told me to stop; tell me what to do, or say 'carry on'.");
    }

    @Test
    void goBackToWhereYouStartedGoesToTheStartNotToWhereItWasLastTold() throws Exception {
        Point2[] walk = Games.freeWalk(SEED, 10);
        Listener pupil = new Listener();
        GameListener teacher = script(pupil, Map.of(
                2L, "go south 10 metres and wait",
                100L, "walk 5 metres north and wait",
                200L, "go back to where you started"));

        Games.play(SEED, 20, List.of(pupil), Games.at(Map.of("Pupil", walk[1].at(0))), teacher);

        assertThat(pupil.said).as("said").contains("Going to where I started.");
        Point2 back = pupil.whereItSaid("I'm back where I started.");
        Point2 lastTold = pupil.whereItSaid("Going 5 metres north, then waiting here.");
        assertThat(back.distance(pupil.track.get(0))).as("from the start, back at %s; said %s", back, pupil.said)
                .isLessThan(1.5);
        assertThat(lastTold.distance(pupil.track.get(0))).as("precondition: last told away from the start")
                .isGreaterThan(3);
    }

    @Test
    void collectTwoBananasAndBringThemToMeDoesBothAndComesBack() throws Exception {
        Listener pupil = new Listener();
        List<String> eaten = new CopyOnWriteArrayList<>();
        GameListener listener = new GameListener() {
            @Override
            public void fruitEaten(String agent, String fruitId, FruitKind kind, double time) {
                if (agent.equals("Pupil") && kind == FruitKind.BANANA) {
                    eaten.add(fruitId);
                }
            }
        };
        Point2 start = Games.freeWalk(SEED, 12)[0];
        pupil.instruct("collect 2 bananas and bring them to me");

        Games.play(SEED, 40, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), listener);

        assertThat(pupil.said.get(0)).isEqualTo("Going to pick up two bananas, then coming back.");
        assertThat(pupil.said).as("said").anyMatch(s -> s.startsWith("Done: I collected 2, the last the banana "));
        assertThat(eaten).as("bananas collected; said %s", pupil.said).hasSizeGreaterThanOrEqualTo(2);
        Point2 back = pupil.whereItSaid("I'm back.");
        assertThat(back.distance(pupil.track.get(0))).as("back where it was told, at %s", back).isLessThan(1.5);
    }

    @Test
    void aWalkThatEndsInTheRiverIsCutShortWithTheReasonSaid() throws Exception {
        Point2 start = shoreWalk();
        Listener pupil = new Listener();
        pupil.instruct("head north for 15 metres");

        Games.play(SEED, 15, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))));

        assertThat(pupil.said.get(0)).isEqualTo("Going 15 metres north.");
        assertThat(pupil.said.get(1)).as("said %s", pupil.said)
                .startsWith("That point is in the river; the nearest place I can stand that way is ");
        assertThat(pupil.said).anyMatch(s -> s.contains("not the 15 metres you asked: further is in the river."));
        assertThat(pupil.track).as("never in the water").noneMatch(p -> world.river().contains(p));
    }

    @Test
    void theTableBehindYouIsTheOneBehindTheAgentAsItFacedWhenTold() throws Exception {
        Table south = world.tables().stream().filter(t -> freeNorthOf(t.position()) != null).findFirst()
                .orElseThrow(() -> new IllegalStateException("no table with a free place north of it"));
        Point2 start = freeNorthOf(south.position());
        Listener pupil = new Listener();
        pupil.instruct("face north and wait");
        GameListener teacher = script(pupil, Map.of(40L, "go to the table behind you"));

        Games.play(SEED, 8, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), teacher);

        String arrived = pupil.said.stream().filter(s -> s.startsWith("I'm at the table ")).findFirst()
                .orElseThrow(() -> new AssertionError("did not reach a table; said " + pupil.said));
        String id = arrived.substring("I'm at the table ".length()).replaceAll("[.].*", "");
        Table table = world.tables().stream().filter(t -> t.id().equals(id)).findFirst().orElseThrow();
        int told = pupil.saidAt.get(pupil.said.indexOf("Going to a table behind me."));
        double bearing = Bearings.bearing(pupil.track.get(told - 1), pupil.headings.get(told - 1), table.position());
        assertThat(Math.abs(bearing)).as("bearing of %s from where it was told", id)
                .isGreaterThan(Math.toRadians(120));
    }

    @Test
    void aSentenceInAnotherLanguageIsAnsweredInEnglish() throws Exception {
        Listener pupil = new Listener();
        pupil.instruct("nimm bitte die Banane");

        Games.play(SEED, 2, List.of(pupil));

        assertThat(pupil.said).containsExactly("I understand only English, and that looks like German; say, for "
                + "example, 'pick up the banana' or 'go to the castle'.");
    }

    /** A free place 12 units north of this point (north is -z), on the same bank; null when there is none. */
    private Point2 freeNorthOf(Point2 table) {
        Point2 p = new Point2(table.x(), table.z() - 12);
        for (int i = 0; i <= 12; i++) {
            if (world.river().contains(new Point2(table.x(), table.z() - i))) {
                return null;
            }
        }
        return world.checkPlace(p, 1.2).isFree() ? p : null;
    }

    /** A free place from which 15 units north is in the river and 5 units north is not. */
    private Point2 shoreWalk() {
        for (double x = -90; x <= 90; x += 3) {
            for (double z = -90; z <= 90; z += 1) {
                Point2 p = new Point2(x, z);
                Point2 far = new Point2(x, z - 15);
                Point2 near = new Point2(x, z - 5);
                if (world.checkPlace(p, 1.2).isFree() && !world.river().contains(p) && world.river().contains(far)
                        && world.checkMove(p, near, 1).isFree() && !world.river().contains(near)) {
                    return p;
                }
            }
        }
        throw new IllegalStateException("no place 15 units south of the river in the world of seed " + SEED);
    }

    private static String compass(double heading) {
        return Sector.of(-Math.sin(heading), -Math.cos(heading)).wireName();
    }
}
