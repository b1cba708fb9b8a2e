package io.orchard.agents;

import static io.orchard.agents.ErrandScript.CARRYING_ON;
import static io.orchard.agents.ErrandScript.off;
import static io.orchard.agents.ErrandScript.Step.step;
import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.ErrandScript.Errand;
import io.orchard.agents.ErrandScript.Step;
import io.orchard.agents.ErrandScript.Window;
import io.orchard.agents.language.InstructionSets;
import io.orchard.agents.language.Language;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.Bank;
import io.orchard.server.world.Bridge;
import io.orchard.server.world.Table;
import io.orchard.server.world.Tree;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.ToDoubleFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Instructions of {@code language/unseen.tsv}, invented to judge the grammar afresh, with some of
 * the other sets, carried out as real errands in recorded lockstep games on port 0
 * ({@link ErrandScript}): each checked in the recording against the world, from the tick the agent
 * took it to the tick it said it was done.
 */
class UnseenErrandsGameTest {

    private static final long SEED = InstructedAgentTest.SEED;

    private final World world = WorldGenerator.standard(SEED).generate();

    @TempDir
    Path recordings;

    private void play(String name, Point2 start, double seconds, List<Step> steps, Errand agent,
                      List<AgentController> others) throws Exception {
        Set<String> sentences = new HashSet<>(InstructionSets.unseen());
        sentences.addAll(InstructionSets.sentences());
        ErrandScript.play(SEED, recordings.resolve(name + ".ndjson"), start, seconds, steps, sentences, agent, others);
    }

    private void play(String name, Point2 start, double seconds, List<Step> steps) throws Exception {
        play(name, start, seconds, steps, new Errand(), List.of());
    }

    // ---- walking, turning and questions -----------------------------------------------------------

    @Test
    void walkingTurningAndQuestions() throws Exception {
        Point2 start = Games.freeWalk(SEED, 12)[0];
        Point2 castle = world.castle().centre();
        play("walking", start, 200, List.of(
                step("first walk 5 metres north, then turn right", "Done: I'm facing east\\." + CARRYING_ON.substring(2),
                        w -> {
                            assertThat(w.end().z() - w.start().z()).as("%s", w).isBetween(-6.2, -3.8);
                            assertThat(Math.abs(w.end().x() - w.start().x())).as("%s", w).isLessThan(1.2);
                            assertThat(off(w.endHeading(), -Math.PI / 2)).as("facing east").isLessThan(0.1);
                        }),
                step("walk norht 10 metres", CARRYING_ON,
                        w -> assertThat(w.end().z() - w.start().z()).as("%s", w).isBetween(-11.2, -8.8)),
                step("go 5 metres to your left", CARRYING_ON,
                        w -> assertThat(w.along(w.end(), w.startHeading() + Math.PI / 2)).as("%s", w).isBetween(3.8, 6.2)),
                step("how many coconuts do you have?", "I haven't collected any coconuts yet\\.", w -> { }),
                step("do you have any coconuts?", "I haven't collected any coconuts yet\\.", w -> { }),
                step("what are you holding?", "I haven't collected any fruit yet\\.", w -> { }),
                step("tell me your rules", "I have no rules.*", w -> { }),
                step("how far is the castle?", "The castle is \\d+ m to the .*", w -> {
                    Matcher m = Pattern.compile("The castle is (\\d+) m").matcher(w.last());
                    assertThat(m.find()).isTrue();
                    assertThat(Double.parseDouble(m.group(1))).as("%s", w)
                            .isBetween(w.end().distance(castle) - 25, w.end().distance(castle) + 25);
                }),
                step("what is the nearest fruit?", "The \\w+ F\\d+ is \\d+ m .*", w -> {
                    String id = fruitNamed(w.last());
                    double named = fruit(id).position().onGround().distance(w.end());
                    assertThat(w.knew).as("%s: known fruit nearer than the one named", w)
                            .noneMatch(f -> f.ground().distance(w.end()) < named - 0.5);
                }),
                step("lauf zum großen Baum", "I understand only English, and that looks like German.*",
                        w -> assertThat(w.end().distance(w.start())).isLessThan(0.05)),
                step("swim to the other bank", "I didn't understand 'swim to the other bank'.*", still()),
                step("climb the tallest palm", "I didn't understand 'climb the tallest palm'.*", still()),
                step("go halfway to the castle", "I didn't understand 'go halfway to the castle'.*", still()),
                step("turn left, walk 3 metres and look around", "Done: I moved\\.", w -> {
                    // it goes on to look around, turning as it does: the walk shows the turn, a quarter left
                    assertThat(w.along(w.end(), w.startHeading() + Math.PI / 2)).as("%s", w).isBetween(2.2, 3.8);
                    assertThat(Math.abs(w.along(w.end(), w.startHeading()))).as("%s", w).isLessThan(0.8);
                })));
    }

    /** A walk that cannot go the whole way: it says how far it went, and that is how far it went. */
    @Test
    void aWalkIntoTheCastleSaysHowFarItWent() throws Exception {
        Point2 wall = world.castle().centre();
        while (!world.checkPlace(wall, 1.2).isFree()) {
            wall = new Point2(wall.x(), wall.z() + 0.5);
        }
        Point2 start = Places.freeNear(world, new Point2(wall.x(), wall.z() + 4));
        play("castle-wall", start, 60, List.of(
                step("walk norht 10 metres", "(Done: I went|I went only) \\d+ metres? north, not the 10 metres you asked: .*", w -> {
                    Matcher m = Pattern.compile("I went (?:only )?(\\d+) metre").matcher(w.last());
                    assertThat(m.find()).isTrue();
                    double went = w.start().z() - w.end().z();
                    assertThat(Double.parseDouble(m.group(1))).as("%s: went %.1f", w, went).isBetween(went - 1, went + 1);
                })));
    }

    private static java.util.function.Consumer<Window> still() {
        return w -> assertThat(w.end().distance(w.start())).as("%s", w).isLessThan(0.05);
    }

    // ---- fruit ---------------------------------------------------------------------------------------

    @Test
    void fruitChosenByPlaceAndSuperlativeAndWhereItWasFoundAgain() throws Exception {
        Point2 start = Places.freeNear(world, new Point2(-5, -42));
        assertThat(world.bankOf(start)).contains(Bank.NORTH);
        play("fruit", start, 300, List.of(
                step("pick up the coconut behind you", picked("coconut"), w -> {
                    FruitState coconut = only(w, FruitKind.COCONUT);
                    double bearing = Bearings.bearing(w.start(), w.startHeading(), coconut.position().onGround());
                    assertThat(Math.abs(bearing)).as("behind: %s", w).isGreaterThan(Math.toRadians(115));
                }),
                step("grab the lowest coconut", picked("coconut"), w -> {
                    FruitState coconut = only(w, FruitKind.COCONUT);
                    assertThat(w.knew).as("%s: a lower coconut known", w).noneMatch(f -> f.kind() == FruitKind.COCONUT
                            && f.height() < coconut.position().y() - 0.01);
                }),
                step("go back to where you found the coconut", "Done: I went to where I found .*",
                        w -> assertThat(w.end().distance(w.previous.taken.get(0).position().onGround())).as("%s", w)
                                .isLessThan(2.5))));
    }

    private static String picked(String kind) {
        return "Done: I picked up the " + kind + " F\\d+\\." + CARRYING_ON.substring(2);
    }

    private static FruitState only(Window w, FruitKind kind) {
        assertThat(w.taken).as("%s", w).hasSize(1);
        assertThat(w.taken.get(0).kind()).as("%s", w).isEqualTo(kind);
        return w.taken.get(0);
    }

    private FruitState fruit(String id) {
        return Games.fruitOf(SEED).stream().filter(f -> f.id().equals(id)).findFirst().orElseThrow();
    }

    private static String fruitNamed(String line) {
        Matcher m = Pattern.compile("(F\\d+)").matcher(line);
        assertThat(m.find()).as("a fruit named in '%s'", line).isTrue();
        return m.group(1);
    }

    private static Point2 middle(Bridge bridge) {
        return new Point2((bridge.entryA().x() + bridge.entryB().x()) / 2, (bridge.entryA().z() + bridge.entryB().z()) / 2);
    }

    // ---- landmarks, bridges and rules ---------------------------------------------------------------

    @Test
    void landmarksBridgesAndRules() throws Exception {
        Point2 castle = world.castle().centre();
        Bridge south = world.bridges().stream().max(Comparator.comparingDouble(b -> middle(b).z())).orElseThrow();
        Point2 start = Places.freeNear(world, new Point2(-8, 10));
        assertThat(world.bankOf(start)).as("precondition: the start is on the south bank").contains(Bank.SOUTH);
        play("landmarks", start, 400, List.of(
                step("go to the table to your left", "I'm at the table D\\d+\\." + CARRYING_ON.substring(2), w -> {
                    Table table = table(w);
                    double bearing = Bearings.bearing(w.start(), w.startHeading(), table.position());
                    assertThat(bearing).as("on its left: %s", w).isBetween(Math.toRadians(25), Math.toRadians(155));
                }),
                step("walk to the closest tree in front of you", "I'm at the tree T\\d+\\." + CARRYING_ON.substring(2),
                        w -> {
                            Tree tree = tree(w);
                            double bearing = Bearings.bearing(w.start(), w.startHeading(), tree.position());
                            assertThat(Math.abs(bearing)).as("ahead: %s", w).isLessThan(Math.toRadians(65));
                        }),
                step("go to the tree closest to the castle", "I'm at the tree T\\d+\\." + CARRYING_ON.substring(2),
                        w -> assertThat(tree(w).position().distance(castle)).as("%s", w)
                                .isLessThanOrEqualTo(nearest(world.trees(), t -> t.position().distance(castle),
                                        w) + 0.01)),
                step("walk to the easternmost table", "I'm at the table D\\d+\\." + CARRYING_ON.substring(2),
                        w -> assertThat(table(w).position().x()).as("%s", w).isGreaterThanOrEqualTo(
                                -nearest(world.tables(), t -> -t.position().x(), w) - 0.01)),
                step("go to the biggest tree south of the river", "I'm at the tree T\\d+\\." + CARRYING_ON.substring(2),
                        w -> {
                            Tree tree = tree(w);
                            assertThat(world.bankOf(tree.position())).as("%s", w).contains(Bank.SOUTH);
                            if (w.said.stream().anyMatch(line -> line.startsWith("I don't know of a tree"))) {
                                return; // it said it knew of none there, so it looked and took the first it found
                            }
                            assertThat(tree.crownRadius()).as("%s", w).isGreaterThanOrEqualTo(-nearest(
                                    world.trees().stream().filter(t -> world.bankOf(t.position()).equals(
                                            java.util.Optional.of(Bank.SOUTH))).toList(), t -> -t.crownRadius(),
                                    w) - 0.01);
                        }),
                step("go to the neerest tabel", "I'm at the table D\\d+\\." + CARRYING_ON.substring(2),
                        w -> assertThat(table(w).position().distance(w.start())).as("%s", w).isLessThanOrEqualTo(
                                nearest(world.tables(), t -> t.position().distance(w.start()), w) + 0.01)),
                step("would you please walk over to the castle", "I'm at the castle\\." + CARRYING_ON.substring(2),
                        w -> assertThat(w.end().distance(castle)).as("%s", w).isLessThan(20)),
                step("stay on your side of the river", "From now on I'll stay on this side of the river\\.", w -> { }),
                step("cross the river by the southern bridge", "I won't: that is against your rule .*",
                        w -> assertThat(w.ticks()).as("%s", w).allSatisfy(t -> assertThat(world.bankOf(t.at()))
                                .isNotEqualTo(java.util.Optional.of(Bank.NORTH)))),
                step("you're allowed to cross the river again", "All right: I may go to the other side of the river "
                        + "again\\.", w -> { }),
                crossing("cross the river by the southern bridge", south),
                crossing("go to the bridge, cross it and then explore", null),
                step("keep out of the forest", "From now on I won't go into the forest\\.", w -> { }),
                step("explore the woods on the other side of the river", "I won't: that is against your rule .*forest.*",
                        w -> assertThat(w.said).as("refused before setting out: %s", w).hasSize(1))));
    }

    /** Crossing the river: over the bridge (the one named, when given), to the other bank, never through the water. */
    private Step crossing(String sentence, Bridge over) {
        return step(sentence, "I'm on the other side of the river, over the bridge B\\d+\\.(" + CARRYING_ON.substring(2)
                + ")?", w -> {
                    Bridge bridge = bridge(w);
                    if (over != null) {
                        assertThat(bridge.id()).as("%s", w).isEqualTo(over.id());
                    }
                    assertThat(world.bankOf(w.end())).as("%s", w).isPresent().isNotEqualTo(world.bankOf(w.start()));
                    assertThat(w.ticks()).as("in the water").noneMatch(t -> world.river().contains(t.at())
                            && world.bridges().stream().noneMatch(b -> b.covers(t.at())));
                });
    }

    /**
     * The least value of {@code measure} over the things the agent knew of when told: it can choose
     * only among those, and it knew of at least one, since it went to one.
     */
    private static <T> double nearest(List<T> things, ToDoubleFunction<T> measure, Window told) {
        return things.stream().filter(t -> told.knewObstacles.contains(id(t))).mapToDouble(measure).min()
                .orElseThrow(() -> new AssertionError("the agent knew of none of them when told: " + told));
    }

    private static String id(Object thing) {
        return thing instanceof Tree tree ? tree.id() : ((Table) thing).id();
    }

    private Table table(Window w) {
        String id = named(w, "table (D\\d+)");
        return world.tables().stream().filter(t -> t.id().equals(id)).findFirst().orElseThrow();
    }

    private Tree tree(Window w) {
        String id = named(w, "tree (T\\d+)");
        return world.trees().stream().filter(t -> t.id().equals(id)).findFirst().orElseThrow();
    }

    private Bridge bridge(Window w) {
        String id = named(w, "bridge (B\\d+)");
        return world.bridges().stream().filter(b -> b.id().equals(id)).findFirst().orElseThrow();
    }

    private static String named(Window w, String pattern) {
        Matcher m = Pattern.compile(pattern).matcher(w.last());
        assertThat(m.find()).as("'%s' in '%s'", pattern, w.last()).isTrue();
        return m.group(1);
    }

    // ---- German --------------------------------------------------------------------------------------

    @Test
    void anAgentThatSpeaksGermanCarriesOutGermanErrandsAndAnswersInGerman() throws Exception {
        Point2 start = Places.freeNear(world, new Point2(-5, -42));
        play("german", start, 200, List.of(
                step("wie viele Bananen hast du?", "Ich habe noch keine Bananen gesammelt\\.", w -> { }),
                step("heb die Kokosnuss hinter dir auf", "Erledigt: .*", w -> {
                    FruitState coconut = only(w, FruitKind.COCONUT);
                    double bearing = Bearings.bearing(w.start(), w.startHeading(), coconut.position().onGround());
                    assertThat(Math.abs(bearing)).as("behind: %s", w).isGreaterThan(Math.toRadians(115));
                }),
                step("geh bitte zur nächsten Brücke", "Ich bin bei der Brücke B\\d+\\..*", w -> { })),
                new Errand(Language.GERMAN), List.of());
    }
}
