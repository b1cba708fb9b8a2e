package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.behaviour.Explorer;
import io.orchard.agents.behaviour.Status;
import io.orchard.agents.zoo.Bunny;
import io.orchard.agents.zoo.Dwarf;
import io.orchard.agents.zoo.Guppy;
import io.orchard.agents.zoo.Recording;
import io.orchard.agents.zoo.Roadrunner;
import io.orchard.agents.zoo.Robot;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.server.sim.GameListener;
import io.orchard.server.world.Bank;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Rules that hold until lifted, in real lockstep games: the agents' own foraging, planning and
 * exploring obey them, not only the errands; the paper's zoo obeys them in each agent's own
 * architecture; a rule is restated, listed when asked, lifted, and named when it refuses an
 * errand; a condition is acted on whenever it comes true.
 */
class RulesGameTest {

    private static final long SEED = InstructedAgentTest.SEED;
    private static final int TICKS_PER_SECOND = 20;

    private final World world = WorldGenerator.standard(SEED).generate();

    @TempDir
    Path recordings;

    /** An agent with the default behaviour that notes where it stood, what it said and what it took. */
    static class Pupil extends AgentController {
        final List<Point2> track = new CopyOnWriteArrayList<>();
        final List<Long> ticks = new CopyOnWriteArrayList<>();
        final List<String> said = new CopyOnWriteArrayList<>();

        Pupil(String name) {
            super(name);
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

    /** An agent whose own behaviour only explores: it takes fruit only when a condition tells it to. */
    static final class Scout extends Pupil {
        Scout() {
            super("Scout");
        }

        @Override
        protected void decide(Perception perception) {
            track.add(position());
            ticks.add(tick());
            if (!pursueInstruction()) {
                explore();
            }
        }

        private Explorer explorer;

        private void explore() {
            if (explorer == null) {
                explorer = new Explorer(memory(), planner());
            }
            if (explorer.step(forager().navigator()) == Status.DONE) {
                halt();
            }
        }
    }

    /** Who took which fruit, as the server tells it, in order. */
    static final class Eaten implements GameListener {
        final Map<String, List<FruitKind>> kinds = new ConcurrentHashMap<>();
        final Map<String, List<Double>> times = new ConcurrentHashMap<>();
        final Map<String, List<String>> ids = new ConcurrentHashMap<>();

        @Override
        public void fruitEaten(String agent, String fruitId, FruitKind kind, double time) {
            kinds.computeIfAbsent(agent, a -> new CopyOnWriteArrayList<>()).add(kind);
            times.computeIfAbsent(agent, a -> new CopyOnWriteArrayList<>()).add(time);
            ids.computeIfAbsent(agent, a -> new CopyOnWriteArrayList<>()).add(fruitId);
        }

        List<FruitKind> by(String agent) {
            return kinds.getOrDefault(agent, List.of());
        }

        /** The kinds the agent took before (or, when {@code before} is false, from) that time. */
        List<FruitKind> by(String agent, double time, boolean before) {
            List<FruitKind> taken = new ArrayList<>();
            List<FruitKind> all = by(agent);
            List<Double> when = times.getOrDefault(agent, List.of());
            for (int i = 0; i < all.size(); i++) {
                if ((when.get(i) < time) == before) {
                    taken.add(all.get(i));
                }
            }
            return taken;
        }
    }

    /** A listener of the game that gives agents sentences at the ticks of a script. */
    private static GameListener script(Map<Long, Runnable> lines) {
        return new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                Runnable line = lines.get(tick);
                if (line != null) {
                    line.run();
                }
            }
        };
    }

    private static GameListener both(GameListener first, GameListener second) {
        return new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                first.tickEnded(tick, time);
                second.tickEnded(tick, time);
            }

            @Override
            public void fruitEaten(String agent, String fruitId, FruitKind kind, double time) {
                first.fruitEaten(agent, fruitId, kind, time);
                second.fruitEaten(agent, fruitId, kind, time);
            }
        };
    }

    @Test
    void stayOnThisSideAndOnlyBananasHoldForTheAgentsOwnForagingUntilLifted() throws Exception {
        Pupil pupil = new Pupil("Pupil");
        Eaten eaten = new Eaten();
        pupil.instruct("stay on this side of the river");
        pupil.instruct("only bananas from now on");
        long lift = 60L * TICKS_PER_SECOND;
        GameListener teacher = script(Map.of(
                10L, () -> pupil.instruct("what are your rules?"),
                lift, () -> pupil.instruct("forget the rules"),
                lift + 4, () -> pupil.instruct("what are your rules?")));

        Games.play(SEED, 100, List.of(pupil), (name, radius) -> null, both(teacher, eaten));

        Bank start = world.bankOf(pupil.track.get(0)).orElseThrow();
        List<Point2> ruled = pupil.track.subList(0, Math.min(pupil.track.size(), (int) lift));
        assertThat(ruled).as("on the other bank while the rule held; said %s", pupil.said)
                .noneMatch(p -> world.bankOf(p).map(bank -> bank != start).orElse(false));
        assertThat(pupil.said).startsWith("From now on I'll stay on this side of the river.",
                "From now on I'll collect only bananas.");
        assertThat(pupil.said).contains("My rules: I stay on this side of the river; I collect only bananas. Say "
                + "'forget the rules' to lift them.", "All right: I've forgotten all my rules.",
                "I have no rules: I go where I like and take any fruit I can reach.");
        List<FruitKind> underTheRule = eaten.by("Pupil", lift / (double) TICKS_PER_SECOND, true);
        assertThat(underTheRule).as("taken while only bananas; said %s", pupil.said).isNotEmpty()
                .containsOnly(FruitKind.BANANA);
        assertThat(eaten.by("Pupil", lift / (double) TICKS_PER_SECOND, false)).as("taken once the rules were lifted")
                .anyMatch(kind -> kind != FruitKind.BANANA);
    }

    @Test
    void theZooKeepsToFruitRulesEachInItsOwnArchitecture() throws Exception {
        Map<String, String> rules = new HashMap<>();
        rules.put("Dwarf", "only bananas from now on");
        rules.put("Robot", "leave the coconuts");
        rules.put("Bunny", "don't eat the tomatoes");
        rules.put("Guppy", "ignore the bananas");
        rules.put("Roadrunner", "only coconuts from now on");
        List<AgentController> zoo = List.of(new Dwarf(), new Robot(), new Bunny(), new Guppy(), new Roadrunner());
        Map<String, List<String>> said = new ConcurrentHashMap<>();
        for (AgentController agent : zoo) {
            agent.addSpeechListener(text -> said.computeIfAbsent(agent.name(), a -> new CopyOnWriteArrayList<>())
                    .add(text));
            agent.instruct(rules.get(agent.name()));
        }
        Eaten eaten = new Eaten();

        Games.play(SEED, 60, zoo, (name, radius) -> null, eaten);

        assertThat(eaten.by("Dwarf")).as("the Dwarf; said %s", said.get("Dwarf")).containsOnly(FruitKind.BANANA);
        assertThat(eaten.by("Robot")).as("the Robot").doesNotContain(FruitKind.COCONUT);
        assertThat(eaten.by("Bunny")).as("the Bunny").doesNotContain(FruitKind.TOMATO);
        assertThat(eaten.by("Guppy")).as("Guppy").doesNotContain(FruitKind.BANANA);
        assertThat(eaten.by("Roadrunner")).as("the Roadrunner").containsOnly(FruitKind.COCONUT);
        int taken = zoo.stream().mapToInt(agent -> eaten.by(agent.name()).size()).sum();
        assertThat(taken).as("fruit the zoo took under its rules: %s", eaten.kinds).isGreaterThanOrEqualTo(8);
        assertThat(zoo.stream().filter(agent -> !eaten.by(agent.name()).isEmpty()).count())
                .as("agents that took fruit: %s", eaten.kinds).isGreaterThanOrEqualTo(4);
    }

    @Test
    void theZooStaysOnItsBankWhenToldToAndCrossesWhenNot() throws Exception {
        Map<String, Bank> crossedTo = crossings(false);
        Map<String, Bank> crossedUnderTheRule = crossings(true);

        assertThat(crossedTo).as("agents of the zoo that crossed the river on their own").isNotEmpty();
        assertThat(crossedUnderTheRule).as("agents of the zoo that crossed it told to stay on this side").isEmpty();
    }

    /** The agents of the zoo that stood on the other bank from their start within 60 s, with that bank. */
    private Map<String, Bank> crossings(boolean ruled) throws Exception {
        List<AgentController> zoo = List.of(new Dwarf(), new Robot(), new Bunny(), new Guppy(), new Roadrunner());
        for (AgentController agent : zoo) {
            if (ruled) {
                agent.instruct("stay on this side of the river");
            }
        }
        Path file = recordings.resolve(ruled ? "ruled.ndjson" : "free.ndjson");
        Games.recorded(SEED, 60, zoo, (name, radius) -> null, new GameListener() { }, file);
        Map<String, Bank> crossed = new HashMap<>();
        for (AgentController agent : zoo) {
            List<Recording.Tick> track = Recording.read(file, agent.name()).ticks();
            Bank start = world.bankOf(track.get(0).at()).orElseThrow();
            track.stream().map(tick -> world.bankOf(tick.at())).flatMap(Optional::stream)
                    .filter(bank -> bank != start).findFirst().ifPresent(bank -> crossed.put(agent.name(), bank));
        }
        return crossed;
    }

    @Test
    void dontGoNearTheRiverKeepsTheAgentAwayAndRefusesAnErrandThere() throws Exception {
        Point2 start = nearTheRiver(16);
        Pupil pupil = new Pupil("Pupil");
        pupil.instruct("don't go near the river");
        GameListener teacher = script(Map.of(100L, () -> pupil.instruct("go to the river")));

        Games.play(SEED, 45, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), teacher);

        assertThat(pupil.said.get(0)).isEqualTo("From now on I won't go near the river.");
        assertThat(pupil.said).as("said").anyMatch(s -> s.equals("I won't go to the river: that is against your rule "
                + "not to go near the river. Carrying on by myself."));
        double nearest = pupil.track.stream().mapToDouble(p -> Places.toWater(world, p)).min().orElseThrow();
        assertThat(nearest).as("nearest it came to the water, from %.1f; said %s", Places.toWater(world, start), pupil.said)
                .isGreaterThan(7);
        assertThat(pupil.track.get(pupil.track.size() - 1).distance(start)).as("it kept foraging")
                .isGreaterThan(5);
    }

    @Test
    void whenYouSeeABananaTakeItIsDoneEachTimeOneIsSeen() throws Exception {
        Scout scout = new Scout();
        Eaten eaten = new Eaten();
        scout.instruct("when you see a banana, take it");
        GameListener teacher = script(Map.of(30L * TICKS_PER_SECOND, () -> scout.instruct("forget the rules")));

        Games.play(SEED, 50, List.of(scout), Games.at(Map.of("Scout", Games.freeWalk(SEED, 12)[0].at(0))),
                both(teacher, eaten));

        assertThat(scout.said.get(0)).isEqualTo("From now on, whenever I see a banana, I'll pick it up.");
        assertThat(scout.said).as("said").anyMatch(s -> s.matches("I see the banana F\\d+, so as you told me:"));
        assertThat(scout.said).anyMatch(s -> s.matches("Going to pick up the banana F\\d+\\."));
        assertThat(eaten.by("Scout", 30, true)).as("taken while the condition held; said %s", scout.said)
                .hasSizeGreaterThanOrEqualTo(2).containsOnly(FruitKind.BANANA);
        assertThat(eaten.by("Scout", 31, false)).as("taken once it was lifted: it only explores").isEmpty();
    }

    @Test
    void thatTableIsTheTableTheAgentJustSpokeOf() throws Exception {
        Map<String, Integer> onTables = new HashMap<>();
        Games.fruitOf(SEED).stream().filter(f -> f.support() != null && f.support().startsWith("D"))
                .forEach(f -> onTables.merge(f.support(), 1, Integer::sum));
        String table = onTables.entrySet().stream().filter(e -> e.getValue() >= 2).map(Map.Entry::getKey).sorted()
                .findFirst().orElseThrow(() -> new AssertionError("no table with two fruit in the world of the seed"));
        Point2 at = world.tables().stream().filter(t -> t.id().equals(table)).findFirst().orElseThrow().position();
        Point2 start = Places.freeNear(world, new Point2(at.x() + 4, at.z() + 4));
        Pupil pupil = new Pupil("Pupil");
        Eaten eaten = new Eaten();
        pupil.instruct("go to the nearest table and wait");
        GameListener teacher = script(Map.of(160L, () -> pupil.instruct("collect everything on that table")));

        Games.play(SEED, 40, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), both(teacher, eaten));

        String told = "Going to pick up all the fruit that lie on the table " + table + ".";
        assertThat(pupil.said).as("said").contains("I'm at the table " + table + ".", told);
        assertThat(pupil.said.subList(pupil.said.indexOf(told), pupil.said.size())).as("said")
                .anyMatch(s -> s.startsWith("Done: I collected " + onTables.get(table) + " and know of no more"));
        Map<String, String> support = new HashMap<>();
        Games.fruitOf(SEED).forEach(f -> support.put(f.id(), f.support()));
        List<String> taken = eaten.ids.getOrDefault("Pupil", List.of());
        assertThat(taken).as("taken").filteredOn(id -> table.equals(support.get(id))).hasSize(onTables.get(table));
    }

    /** A free place about {@code distance} from the water, away from the bridges. */
    private Point2 nearTheRiver(double distance) {
        for (double x = -80; x <= 80; x += 4) {
            for (double z = -80; z <= 80; z += 2) {
                Point2 p = new Point2(x, z);
                if (Math.abs(Places.toWater(world, p) - distance) < 1 && world.checkPlace(p, 1.2).isFree()
                        && world.bridges().stream().allMatch(b -> b.entryA().distance(p) > 25)) {
                    return p;
                }
            }
        }
        throw new IllegalStateException("no place " + distance + " from the river in the world of seed " + SEED);
    }
}
