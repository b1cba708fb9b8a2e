package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Language;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.KnownObstacle;
import io.orchard.agents.zoo.Recording;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.GameListener;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.stream.Collectors;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.regex.Pattern;

/**
 * Errands carried out one after the other in a recorded lockstep game on port 0: the next sentence is
 * given when the agent says the line that ends the last, and the server's recording shows where the
 * agent stood and which way it faced from the tick it took each sentence to the tick it said it was
 * done, and the game which fruit it took. The agent's own behaviour does nothing, so that whatever it
 * did between those ticks it did for the errand.
 */
final class ErrandScript {

    static final int TICKS_PER_SECOND = 20;

    /** The end of the last line an errand says once it is over. */
    static final String CARRYING_ON = ".* Carrying on by myself\\.";

    private ErrandScript() {
    }

    /** An agent that does nothing on its own, and notes what it said and when, and what it knew when told. */
    static final class Errand extends AgentController {
        final List<String> said = new CopyOnWriteArrayList<>();
        final List<Long> saidAt = new CopyOnWriteArrayList<>();
        final List<Long> toldAt = new CopyOnWriteArrayList<>();
        /** The fruit it knew of when it was told each sentence, by the sentence's turn. */
        final List<List<KnownFruit>> knewWhenTold = new CopyOnWriteArrayList<>();
        /** The ids of the trees, tables and other obstacles it knew of when told each sentence. */
        final List<Set<String>> obstaclesWhenTold = new CopyOnWriteArrayList<>();

        Errand() {
            this(Language.ENGLISH);
        }

        /** An agent that understands this language besides English. */
        Errand(Language language) {
            super("Errand");
            if (language != Language.ENGLISH) {
                understand(language);
            }
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
            knewWhenTold.add(List.copyOf(memory().fruit()));
            obstaclesWhenTold.add(memory().obstacles().stream().map(KnownObstacle::id).collect(Collectors.toSet()));
            super.onInstruction(text, from);
        }
    }

    /**
     * A sentence, the line the agent says when it is done with it, how many ticks to let pass before
     * the next, and what the game must show.
     */
    record Step(String sentence, Pattern done, int pause, Consumer<Window> check) {

        /** A step whose errand ends with a line that matches {@code done}. */
        static Step step(String sentence, String done, Consumer<Window> check) {
            return new Step(sentence, Pattern.compile(done), 0, check);
        }
    }

    /** What the game showed from the tick an errand was taken to the tick it was said to be done. */
    static final class Window {
        final Step step;
        final Recording recording;
        final long from;
        final long to;
        final List<String> said;
        final List<FruitState> taken;
        /** The fruit the agent knew of when told. */
        final List<KnownFruit> knew;
        /** The ids of the obstacles (trees, tables) the agent knew of when told. */
        final Set<String> knewObstacles;
        final Window previous;

        Window(Step step, Recording recording, long from, long to, List<String> said, List<FruitState> taken,
               List<KnownFruit> knew, Set<String> knewObstacles, Window previous) {
            this.previous = previous;
            this.step = step;
            this.recording = recording;
            this.from = from;
            this.to = to;
            this.said = said;
            this.taken = taken;
            this.knew = knew;
            this.knewObstacles = knewObstacles;
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

        /** The last line said in the window. */
        String last() {
            return said.get(said.size() - 1);
        }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "'%s' from tick %d at %s to %d at %s, said %s, took %s", step.sentence(),
                    from, start(), to, end(), said, taken.stream().map(FruitState::id).toList());
        }
    }

    /**
     * Plays a game of {@code seed} in which {@code agent}, placed at {@code start}, is given the steps'
     * sentences one after the other (each of them one of {@code sentences}), and checks each step in
     * the recording once the game is over. The other agents join after it, where the seed puts them.
     */
    static void play(long seed, Path recording, Point2 start, double seconds, List<Step> steps, Set<String> sentences,
                     Errand agent, List<AgentController> others) throws Exception {
        assertThat(steps).allSatisfy(s -> assertThat(sentences).as("a sentence of the set").contains(s.sentence()));
        Map<String, FruitState> fruit = new HashMap<>();
        Games.fruitOf(seed).forEach(f -> fruit.put(f.id(), f));
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
                if (who.equals(agent.name())) {
                    eatenIds.add(fruitId);
                    eatenAt.add(time);
                }
            }
        };
        List<AgentController> agents = new ArrayList<>();
        agents.add(agent);
        agents.addAll(others);
        Map<String, Vec3> places = Map.of(agent.name(), start.at(0));

        Games.recorded(seed, seconds, agents, Games.at(places), teacher, recording);

        assertThat(to).as("errands done; said %s", agent.said).hasSameSizeAs(steps);
        Recording recorded = Recording.read(recording, agent.name());
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
            previous = new Window(steps.get(i), recorded, a, b, List.copyOf(agent.said.subList(saidFrom.get(i),
                    saidTo.get(i))), taken, agent.knewWhenTold.get(i), agent.obstaclesWhenTold.get(i), previous);
            steps.get(i).check().accept(previous);
        }
    }

    /** How far a heading is from the one wanted, in radians, either way round. */
    static double off(double heading, double wanted) {
        return Math.abs(Math.IEEEremainder(heading - wanted, 2 * Math.PI));
    }
}
