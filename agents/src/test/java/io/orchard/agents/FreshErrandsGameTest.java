package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.InstructionSets;
import io.orchard.agents.zoo.Recording;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import io.orchard.server.sim.GameListener;
import io.orchard.server.world.Bank;
import io.orchard.server.world.Bridge;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Instructions of the fresh set ({@code language/fresh.tsv}), as a new user typed them, carried out
 * as real errands: three lockstep games on port 0, each carrying one errand after the other, the
 * next given when the agent says the last is done; the server's recording of each game shows where
 * the agent stood and which way it faced from the tick it took an instruction to the tick it said it
 * was done, and the game which fruit it took. The agent's own behaviour does nothing, so that
 * whatever it did between those ticks it did for the errand.
 */
class FreshErrandsGameTest {

    private static final long SEED = InstructedAgentTest.SEED;
    private static final int TICKS_PER_SECOND = 20;
    private static final String CARRYING_ON = ".* Carrying on by myself\\.";

    private final World world = WorldGenerator.standard(SEED).generate();
    private final Map<String, FruitState> fruit = new HashMap<>();

    @TempDir
    Path recordings;

    FreshErrandsGameTest() {
        Games.fruitOf(SEED).forEach(f -> fruit.put(f.id(), f));
    }

    /** An agent that does nothing on its own, and notes what it said and when. */
    static final class Errand extends AgentController {
        final List<String> said = new CopyOnWriteArrayList<>();
        final List<Long> saidAt = new CopyOnWriteArrayList<>();
        final List<Long> toldAt = new CopyOnWriteArrayList<>();

        Errand() {
            super("Errand");
            addSpeechListener(text -> {
                saidAt.add(tick());
                said.add(text);
            });
        }

        @Override
        protected AgentBody body() {
            return AgentBody.builder().radius(0.4).speed(8).gripper("hands", 0.7, 0, 2)
                    .sight(35, 2 * Math.PI).build();
        }

        @Override
        protected void decide(Perception perception) {
            pursueInstruction(); // and otherwise stands where it is
        }

        @Override
        protected void onInstruction(String text, String from) {
            toldAt.add(tick());
            super.onInstruction(text, from);
        }
    }

    /**
     * A sentence of the fresh set, the line the agent says when it is done with it, how many ticks to
     * let pass before the next, and what the game must show.
     */
    record Step(String sentence, Pattern done, int pause, Consumer<Window> check) {
    }

    private static Step step(String sentence, String done, Consumer<Window> check) {
        return new Step(sentence, Pattern.compile(done), 0, check);
    }

    /** What the game showed from the tick an errand was taken to the tick it was said to be done. */
    final class Window {
        final Step step;
        final Recording recording;
        final long from;
        final long to;
        final List<String> said;
        final List<FruitState> taken;
        final Window previous;

        Window(Step step, Recording recording, long from, long to, List<String> said, List<FruitState> taken,
               Window previous) {
            this.previous = previous;
            this.step = step;
            this.recording = recording;
            this.from = from;
            this.to = to;
            this.said = said;
            this.taken = taken;
        }

        List<Recording.Tick> ticks() {
            return recording.ticks().stream().filter(t -> t.tick() >= from && t.tick() <= to).toList();
        }

        Point2 start() {
            return at(from);
        }

        Point2 end() {
            return at(to);
        }

        Point2 at(long tick) {
            return recording.ticks().stream().filter(t -> t.tick() >= tick).findFirst().orElseThrow().at();
        }

        double heading(long tick) {
            return recording.ticks().stream().filter(t -> t.tick() >= tick && !Double.isNaN(t.heading()))
                    .findFirst().orElseThrow().heading();
        }

        double startHeading() {
            return heading(from);
        }

        /** Which way it faced once done: a turn sent in a tick shows in the perception of the tick after. */
        double endHeading() {
            return heading(to + 2);
        }

        /** How far the agent went from its start along the heading it had then (negative: backwards). */
        double forward() {
            return along(end(), startHeading());
        }

        double along(Point2 p, double heading) {
            return (p.x() - start().x()) * -Math.sin(heading) + (p.z() - start().z()) * -Math.cos(heading);
        }

        /** The seconds the errand took. */
        double seconds() {
            return (to - from) / (double) TICKS_PER_SECOND;
        }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "'%s' from tick %d at %s to %d at %s, said %s, took %s", step.sentence(),
                    from, start(), to, end(), said, taken.stream().map(FruitState::id).toList());
        }
    }

    /** The games: the agent's place, then its errands, one after the other. */
    private void play(String name, Point2 start, double seconds, List<Step> steps) throws Exception {
        Set<String> fresh = Set.copyOf(InstructionSets.fresh());
        assertThat(steps).allSatisfy(s -> assertThat(fresh).as("a sentence of fresh.tsv").contains(s.sentence()));
        Errand agent = new Errand();
        List<Long> from = new CopyOnWriteArrayList<>();
        List<Long> to = new CopyOnWriteArrayList<>();
        List<Integer> saidFrom = new CopyOnWriteArrayList<>();
        List<Integer> saidTo = new CopyOnWriteArrayList<>();
        List<String> eatenIds = new CopyOnWriteArrayList<>();
        List<Double> eatenAt = new CopyOnWriteArrayList<>();
        GameListener teacher = new GameListener() {
            private int current;
            private long next = 2;
            private boolean given;

            @Override
            public void tickEnded(long tick, double time) {
                if (current >= steps.size() || tick < next) {
                    return;
                }
                Step step = steps.get(current);
                if (!given) {
                    saidFrom.add(agent.said.size());
                    agent.instruct(step.sentence());
                    given = true;
                    return;
                }
                int first = saidFrom.get(current);
                for (int i = first; i < agent.said.size(); i++) {
                    if (step.done().matcher(agent.said.get(i)).matches()) {
                        from.add(agent.toldAt.get(current));
                        to.add(agent.saidAt.get(i));
                        saidTo.add(i + 1);
                        current++;
                        given = false;
                        next = tick + 1 + step.pause();
                        return;
                    }
                }
            }

            @Override
            public void fruitEaten(String who, String fruitId, FruitKind kind, double time) {
                if (who.equals("Errand")) {
                    eatenIds.add(fruitId);
                    eatenAt.add(time);
                }
            }
        };
        Path file = recordings.resolve(name + ".ndjson");

        Games.recorded(SEED, seconds, List.of(agent), Games.at(Map.of("Errand", start.at(0))), teacher, file);

        assertThat(to).as("errands of game %s done; said %s", name, agent.said).hasSameSizeAs(steps);
        Recording recording = Recording.read(file, "Errand");
        Window previous = null;
        for (int i = 0; i < steps.size(); i++) {
            long a = from.get(i);
            long b = to.get(i);
            List<FruitState> taken = new ArrayList<>();
            for (int k = 0; k < eatenIds.size(); k++) {
                long tick = Math.round(eatenAt.get(k) * TICKS_PER_SECOND);
                if (tick >= a && tick <= b + 1) {
                    taken.add(fruit.get(eatenIds.get(k)));
                }
            }
            previous = new Window(steps.get(i), recording, a, b, List.copyOf(agent.said.subList(saidFrom.get(i),
                    saidTo.get(i))), taken, previous);
            steps.get(i).check().accept(previous);
        }
    }

    // ---- game 1: turning and walking --------------------------------------------------------------

    @Test
    void turningAndWalking() throws Exception {
        Point2 start = Games.freeWalk(SEED, 12)[0];
        play("walking", start, 150, List.of(
                step("face south", "Done: I'm facing south." + CARRYING_ON.substring(2),
                        w -> assertThat(off(w.endHeading(), Math.PI)).as("%s", w).isLessThan(0.1)),
                step("turn to your left", CARRYING_ON,
                        w -> assertThat(off(w.endHeading() - w.startHeading(), Math.PI / 2)).as("%s", w).isLessThan(0.1)),
                step("turn 60 degrees right", CARRYING_ON,
                        w -> assertThat(off(w.endHeading() - w.startHeading(), -Math.PI / 3)).as("%s", w).isLessThan(0.1)),
                step("trun around", CARRYING_ON,
                        w -> assertThat(off(w.endHeading() - w.startHeading(), Math.PI)).as("%s", w).isLessThan(0.1)),
                step("take a step back", CARRYING_ON, w -> {
                    assertThat(w.forward()).as("%s", w).isBetween(-5.0, -3.0);
                    assertThat(off(w.endHeading(), w.startHeading())).as("kept facing the way it faced").isLessThan(0.1);
                }),
                step("walk forward a little", CARRYING_ON, w -> assertThat(w.forward()).as("%s", w).isBetween(3.0, 5.0)),
                step("face east and then walk 10 metres", CARRYING_ON, w -> {
                    assertThat(w.end().x() - w.start().x()).as("%s", w).isBetween(8.8, 11.2);
                    assertThat(Math.abs(w.end().z() - w.start().z())).as("%s", w).isLessThan(1.5);
                }),
                step("go south-west for 8 metres", CARRYING_ON, w -> {
                    assertThat(w.end().x() - w.start().x()).as("%s", w).isBetween(-6.9, -4.4);
                    assertThat(w.end().z() - w.start().z()).as("%s", w).isBetween(4.4, 6.9);
                }),
                step("ok, now come back", "I'm back." + CARRYING_ON.substring(2),
                        w -> assertThat(w.end().distance(w.previous.start())).as("%s", w).isLessThan(1.5)),
                step("go north for 10 metres and then turn left", CARRYING_ON, w -> {
                    assertThat(w.end().z() - w.start().z()).as("%s", w).isBetween(-11.2, -8.8);
                    assertThat(off(w.endHeading(), Math.PI / 2)).as("facing west").isLessThan(0.1);
                }),
                step("turn around and go forward 5 metres", CARRYING_ON, w -> {
                    assertThat(off(w.endHeading() - w.startHeading(), Math.PI)).as("%s", w).isLessThan(0.1);
                    assertThat(w.along(w.end(), w.endHeading())).as("%s", w).isBetween(3.8, 6.2);
                }),
                step("head west 30 metres then come back", CARRYING_ON, w -> {
                    assertThat(w.ticks().stream().mapToDouble(t -> w.start().x() - t.at().x()).max().orElseThrow())
                            .as("%s", w).isGreaterThan(25);
                    assertThat(w.end().distance(w.start())).as("back").isLessThan(1.5);
                }),
                step("wait 20 seconds", "Done waiting." + CARRYING_ON.substring(2), w -> {
                    assertThat(w.seconds()).as("%s", w).isGreaterThanOrEqualTo(19.9);
                    assertThat(w.ticks()).allSatisfy(t -> assertThat(t.at().distance(w.start())).isLessThan(0.05));
                }),
                new Step("run north", Pattern.compile("Heading north\\."), 40,
                        w -> assertThat(w.start().z() - w.at(w.to + 40).z()).as("%s", w).isGreaterThan(3)),
                new Step("hey, please stop", Pattern.compile("Stopping\\."), 60, w -> {
                    // the halt is sent in the tick it is told; the walk under way ends within a few ticks
                    for (long tick = w.from + 6; tick < w.from + 60; tick++) {
                        assertThat(w.at(tick).distance(w.at(w.from + 6))).as("still at tick %d; %s", tick, w)
                                .isLessThan(0.02);
                    }
                    assertThat(w.at(w.from + 6).distance(w.start())).as("stopped where it was told").isLessThan(1);
                }),
                step("go back to where you started", "I'm back where I started." + CARRYING_ON.substring(2),
                        w -> assertThat(w.end().distance(start)).as("%s", w).isLessThan(1.5))));
    }

    // ---- game 2: the castle and fruit ----------------------------------------------------------

    @Test
    void theCastleAndFruit() throws Exception {
        Point2 castle = world.castle().centre();
        Point2 start = Places.freeNear(world, new Point2(castle.x() - 25, castle.z() - 15));
        Bank bank = world.bankOf(start).orElseThrow();
        play("castle", start, 300, List.of(
                step("stay on this side of the river", "From now on I'll stay on this side of the river\\.",
                        w -> assertThat(w.recording.ticks()).as("on the other bank, all game long")
                                .allSatisfy(t -> assertThat(world.bankOf(t.at()).orElse(bank)).isEqualTo(bank))),
                step("walk to the castel and wait", "I'm at the castle\\.",
                        w -> assertThat(w.end().distance(castle)).as("%s", w).isLessThan(20)),
                step("go north of the castle", "Done: I went north of the castle\\." + CARRYING_ON.substring(2), w -> {
                    Point2 end = w.end();
                    assertThat(end.z()).as("%s", w).isLessThan(castle.z() - 5);
                    assertThat(Math.abs(Math.atan2(end.x() - castle.x(), castle.z() - end.z()))).as("bearing from the "
                            + "castle").isLessThan(Math.toRadians(65));
                }),
                step("wait by the castle", "Done: I went near the castle\\.",
                        w -> assertThat(w.end().distance(castle)).as("%s", w).isLessThan(25)),
                step("please go to the castle, thank you", "I'm at the castle\\." + CARRYING_ON.substring(2),
                        w -> assertThat(w.end().distance(castle)).as("%s", w).isLessThan(20)),
                step("fetch a coconut and come back to me", "I'm back\\." + CARRYING_ON.substring(2), w -> {
                    assertThat(w.taken).as("%s", w).extracting(FruitState::kind).containsExactly(FruitKind.COCONUT);
                    assertThat(w.end().distance(w.start())).as("back").isLessThan(1.5);
                }),
                step("collect 2 bananas", "Done: I collected 2, the last the banana F\\d+\\." + CARRYING_ON.substring(2),
                        w -> assertThat(w.taken).as("%s", w).extracting(FruitState::kind)
                                .containsExactly(FruitKind.BANANA, FruitKind.BANANA)),
                step("get a tomato from the ground", "Done: I picked up the tomato F\\d+\\." + CARRYING_ON.substring(2),
                        w -> assertThat(w.taken).as("%s", w).singleElement().satisfies(f -> {
                            assertThat(f.kind()).isEqualTo(FruitKind.TOMATO);
                            assertThat(f.support()).as("on the ground").isNull();
                        })),
                step("go to the castle, after that collect a tomato", "Done: I picked up the tomato F\\d+\\."
                        + CARRYING_ON.substring(2), w -> {
                    assertThat(w.taken).as("%s", w).extracting(FruitState::kind).containsExactly(FruitKind.TOMATO);
                    assertThat(w.ticks().stream().mapToDouble(t -> t.at().distance(castle)).min().orElseThrow())
                            .as("went to the castle first: %s", w).isLessThan(20);
                    assertThat(w.said).anyMatch(line -> line.equals("I'm at the castle."));
                })));
    }

    // ---- game 3: the river, its bridges, and a rule ---------------------------------------------

    @Test
    void theRiverItsBridgesAndARule() throws Exception {
        Bridge north = world.bridges().stream().min(java.util.Comparator.comparingDouble(b -> middle(b).z()))
                .orElseThrow();
        Bridge south = world.bridges().stream().max(java.util.Comparator.comparingDouble(b -> middle(b).z()))
                .orElseThrow();
        Point2 start = Places.freeNear(world, new Point2(-8, 10));
        assertThat(world.bankOf(start)).as("precondition: the start is on the south bank").contains(Bank.SOUTH);
        play("river", start, 300, List.of(
                step("don't go near the river", "From now on I won't go near the river\\.",
                        w -> assertThat(w.end().distance(w.start())).as("%s", w).isLessThan(0.05)),
                step("walk over to the river", "I won't go to the river: that is against your rule not to go near the "
                        + "river\\." + CARRYING_ON.substring(2),
                        w -> assertThat(w.end().distance(w.start())).as("%s", w).isLessThan(0.5)),
                step("you can go near the river again", "All right: I may go near the river again\\.", w -> { }),
                step("walk over to the river", "I'm at the river\\." + CARRYING_ON.substring(2),
                        w -> assertThat(Places.toWater(world, w.end())).as("%s", w).isLessThan(6)),
                step("head to the bridge", "I'm at the bridge B\\d+\\." + CARRYING_ON.substring(2), w -> {
                    Bridge bridge = named(w);
                    assertThat(Math.min(w.end().distance(bridge.entryA()), w.end().distance(bridge.entryB())))
                            .as("%s", w).isLessThan(3);
                }),
                step("go to the northern bridge", "I'm at the bridge B\\d+\\." + CARRYING_ON.substring(2), w -> {
                    assertThat(named(w).id()).as("%s", w).isEqualTo(north.id());
                    assertThat(Math.min(w.end().distance(north.entryA()), w.end().distance(north.entryB())))
                            .as("%s", w).isLessThan(3);
                }),
                crossing("cross the river using the northern bridge", north),
                crossing("cross the southern bridge", south),
                crossing("cross the nothern bridge", north),
                crossing("first go to the bridge, then cross it", null),
                step("if you could, go north", "I've gone as far north as I can\\." + CARRYING_ON.substring(2), w -> {
                    assertThat(w.start().z() - w.end().z()).as("%s", w).isGreaterThan(5);
                    assertThat(w.ticks()).noneMatch(t -> world.river().contains(t.at())
                            && world.bridges().stream().noneMatch(b -> b.covers(t.at())));
                })));
    }

    /** Crossing the river: over the bridge (the one named, when given), to the other bank, never through the water. */
    private Step crossing(String sentence, Bridge over) {
        return step(sentence, "I'm on the other side of the river, over the bridge B\\d+\\." + CARRYING_ON.substring(2),
                w -> {
                    Bridge bridge = named(w);
                    if (over != null) {
                        assertThat(bridge.id()).as("%s", w).isEqualTo(over.id());
                    }
                    assertThat(world.bankOf(w.end())).as("%s", w).isPresent().isNotEqualTo(world.bankOf(w.start()));
                    assertThat(w.ticks()).as("on the deck").anyMatch(t -> bridge.covers(t.at()));
                    assertThat(w.ticks()).as("in the water").noneMatch(t -> world.river().contains(t.at())
                            && world.bridges().stream().noneMatch(b -> b.covers(t.at())));
                });
    }

    /** The bridge the last line of the window names. */
    private Bridge named(Window w) {
        String last = w.said.get(w.said.size() - 1);
        java.util.regex.Matcher id = Pattern.compile("bridge (B\\d+)").matcher(last);
        assertThat(id.find()).as("a bridge named in '%s'", last).isTrue();
        return world.bridges().stream().filter(b -> b.id().equals(id.group(1))).findFirst().orElseThrow();
    }

    private static Point2 middle(Bridge bridge) {
        return new Point2((bridge.entryA().x() + bridge.entryB().x()) / 2, (bridge.entryA().z() + bridge.entryB().z()) / 2);
    }

    private static double off(double heading, double wanted) {
        return Math.abs(Math.IEEEremainder(heading - wanted, 2 * Math.PI));
    }
}
