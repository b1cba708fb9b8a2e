package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Harvester;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Ask;
import io.orchard.agents.language.CarryOn;
import io.orchard.agents.language.Collect;
import io.orchard.agents.language.ComeBack;
import io.orchard.agents.language.Cross;
import io.orchard.agents.language.Discourse;
import io.orchard.agents.language.Explore;
import io.orchard.agents.language.Face;
import io.orchard.agents.language.Follow;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.GoTo;
import io.orchard.agents.language.Head;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.Lift;
import io.orchard.agents.language.LookAt;
import io.orchard.agents.language.LookFor;
import io.orchard.agents.language.RelativeMove;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Rule;
import io.orchard.agents.language.Sequence;
import io.orchard.agents.language.Stop;
import io.orchard.agents.language.Turn;
import io.orchard.agents.language.Wait;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * Carries out the goals people give an agent ({@link io.orchard.agents.language.Goal}), with the
 * agent's behaviours: it grounds each goal's references in the agent's {@link WorldMemory} when
 * the goal starts, says what it is doing, pursues the goal a tick at a time, says how it went, and
 * then leaves the agent to its own autonomy.
 *
 * <ul>
 *   <li>Every instruction is answered at once with one line: the goal's restatement ("Going to
 *       pick up a coconut that lies on a table."), a question, or why it cannot be done.
 *   <li>Nothing known fits: the agent says so ("I don't know of a coconut that lies on a table yet;
 *       I'll look for one.") and explores until something fits, then pursues it.
 *   <li>Several trees, tables or bridges fit and nothing in the words picks one: the agent asks
 *       which ({@link #asking()}) and stands still; {@link #answer(String)} reads the reply ("the
 *       nearer one", "the north one", "2"). A new instruction cancels the question; with no reply
 *       for {@value #ANSWER_SECONDS} seconds the agent takes the nearest.
 *   <li>The body cannot do it (a bunny asked for a coconut in a tree): the agent says why and
 *       drops that goal.
 *   <li>Over: the agent says how it went and, after the last step, that it carries on by itself.
 *   <li>A rule ({@link Rule}: "don't go near the river", "only bananas from now on") is taken on at
 *       once and holds until lifted ({@link Lift}), for the errands and for the agent's own behaviour
 *       alike (it goes into the memory's {@link io.orchard.agents.map.Conduct}); the errand under way
 *       goes on under it. An errand that would break a rule is refused, naming it. An agent that finds
 *       itself where a rule keeps it out of leaves first.
 *   <li>A condition ({@link io.orchard.agents.language.WhenSee}: "when you see a banana, take it")
 *       is acted on whenever it comes true while no errand has the agent: the agent says what it saw
 *       and does what it was told for that very thing.
 * </ul>
 *
 * <p>The controller calls {@link #take(Goal)} for each instruction and {@link #step()} every tick
 * it decides; while {@code step()} returns true the goal has the agent, and the agent's own
 * behaviour should rest for that tick. Not thread-safe: it belongs to the controller's thread.
 */
public final class Errands {

    /** How long the agent waits for the answer to a question before it takes the nearest choice. */
    public static final double ANSWER_SECONDS = 30;

    private final Kit kit;
    private final Deque<Goal> steps = new ArrayDeque<>();
    private Goal goal;
    private Pursuit pursuit;
    private Question question;
    private double askedAt;
    private Point2 origin;
    private Point2 previousOrigin;
    private int stepsStarted;
    private boolean stopped;
    private String lastOutcome = "";
    private final Answering answering;
    private final Rulebook rulebook;
    private String leaving;

    /** Errands for the agent {@code motor} drives and {@code memory} remembers for. */
    public Errands(WorldMemory memory, Motor motor) {
        this(memory, motor, new PathPlanner(memory));
    }

    /** Errands that plan their ways with the agent's own {@code planner}, shared with its other behaviours. */
    public Errands(WorldMemory memory, Motor motor, PathPlanner planner) {
        this.kit = new Kit(memory, motor, planner);
        this.rulebook = new Rulebook(kit);
        this.origin = memory.position();
        this.previousOrigin = origin;
        this.answering = new Answering(kit, new Answering.State() {
            @Override
            public String doing() {
                return Errands.this.doing();
            }

            @Override
            public String lastOutcome() {
                return lastOutcome;
            }

            @Override
            public boolean stopped() {
                return stopped;
            }

            @Override
            public Map<FruitKind, Integer> collected() {
                return memory.collected();
            }

            @Override
            public String rules() {
                return rulebook.statements();
            }
        });
    }

    /** The rules in force, oldest first: what the person set and has not lifted. */
    public List<Rule> rules() {
        return rulebook.rules();
    }

    /**
     * What the agent spoke about or looked at last, most recent first: the things its errands went
     * to, turned to, chose or named in answers, for "that table" and "it" in what it is told next.
     */
    public Discourse discourse() {
        return kit.discourse();
    }

    /** What the agent does for the person, in the words of its restatement ("going to the castle"); null when nothing. */
    private @Nullable String doing() {
        if (question != null) {
            return kit.speech.waitingForAnswer(question.text());
        }
        if (leaving != null) {
            return leaving;
        }
        if (goal == null || pursuit == null || goal instanceof Stop) {
            return null;
        }
        String restated = goal.restatement(kit.language);
        return Character.toLowerCase(restated.charAt(0)) + restated.substring(1, restated.length() - 1);
    }

    /**
     * Answers in this language from now on, as the sentence just heard was in it: what the agent says
     * back, says as it goes and answers to questions.
     */
    public void speak(Language language) {
        kit.language = Objects.requireNonNull(language, "language");
    }

    /** The language the agent answers in. */
    public Language language() {
        return kit.language;
    }

    /** The harvester the errands collect with: set its gesture to animate the grasp. */
    public Harvester harvester() {
        return kit.harvester;
    }

    /** The goal being pursued (a sequence's current step); null when none. */
    public @Nullable Goal goal() {
        return goal;
    }

    /** Whether the agent has asked which thing is meant and waits for the answer. */
    public boolean asking() {
        return question != null;
    }

    /** Whether an instructed goal has the agent: one is pursued, or a question waits for its answer. */
    public boolean busy() {
        return pursuit != null || question != null;
    }

    /**
     * Takes a new goal in place of any other (and of any question asked): grounds it, answers the
     * person with one line, and starts it. {@link CarryOn} drops every goal.
     */
    public void take(Goal instructed) {
        if (instructed instanceof Ask ask) {
            kit.motor.say(answering.answer(ask)); // a question leaves the errand as it was
            return;
        }
        List<Goal> all = instructed instanceof Sequence sequence ? sequence.steps() : List.of(instructed);
        if (all.stream().allMatch(Errands::standing)) {
            List<String> said = new ArrayList<>();
            for (Goal rule : all) {
                said.add(standing(rule, false)); // a rule leaves the errand going, under it
            }
            kit.motor.say(String.join(" ", said));
            return;
        }
        start(instructed);
    }

    /** Whether a goal is a rule or lifts one: taken on at once, without an errand of its own. */
    private static boolean standing(Goal goal) {
        return goal instanceof Rule || goal instanceof Lift;
    }

    /** Takes on or lifts a rule; what the agent says of it, or, when {@code quiet}, only what its restatement did not say. */
    private String standing(Goal goal, boolean quiet) {
        String said = goal instanceof Lift lift ? rulebook.lift(lift) : rulebook.take((Rule) goal);
        if (!quiet) {
            return said;
        }
        String restated = goal.restatement(kit.language);
        return said.startsWith(restated) ? said.substring(restated.length()).strip() : said;
    }

    /** Starts a goal of the person's, or of a condition come true, in place of any other. */
    private void start(Goal instructed) {
        leaving = null;
        question = null;
        stopped = instructed instanceof Stop;
        stepsStarted = 0;
        kit.grounder.told(kit.here(), kit.motor.heading());
        pursuit = null;
        goal = null;
        steps.clear();
        kit.navigator.reset();
        previousOrigin = origin;
        origin = kit.here();
        if (instructed instanceof CarryOn) {
            kit.motor.say(instructed.restatement(kit.language));
            return;
        }
        if (instructed instanceof Stop) {
            kit.standStill(); // at once: the halt is sent in this tick
        }
        if (instructed instanceof Sequence sequence) {
            steps.addAll(sequence.steps());
        } else {
            steps.add(instructed);
        }
        String refused = refusal(steps.peek());
        if (refused == null && (standing(steps.peek()) || ambiguity(steps.peek()) == null)) {
            kit.motor.say(instructed.restatement(kit.language));
        }
        next();
    }

    /**
     * Reads a reply to the question asked, if there is one and the reply picks out one of the
     * choices; the goal then goes on with that one.
     *
     * @return whether the text was taken as the answer
     */
    public boolean answer(String text) {
        if (question == null || text == null) {
            return false;
        }
        Optional<Known> picked = question.read(text);
        if (picked.isEmpty()) {
            return false;
        }
        resolve(picked.get(), kit.speech.allRight(picked.get()));
        return true;
    }

    /** The question waiting for its answer, to say again; null when none. */
    public @Nullable String question() {
        return question == null ? null : question.text();
    }

    /**
     * One tick of the instructed goal.
     *
     * @return whether the goal has the agent this tick; false when there is none, and the agent's
     *         own behaviour may act
     */
    public boolean step() {
        if (question == null && pursuit == null && !stopped && kit.memory.conduct().restrictsPlaces()
                && kit.memory.conduct().forbids(kit.here())) {
            leave(); // where a rule keeps it out of: out first
        }
        if (question == null && pursuit == null && !stopped) {
            Watching.Seen seen = rulebook.watching().next();
            if (seen != null) {
                kit.mention(seen.thing());
                kit.motor.say(kit.speech.seenSoAsTold(seen.thing()));
                start(seen.goal());
            }
        }
        if (question != null) {
            kit.standStill();
            if (kit.motor.time() - askedAt >= ANSWER_SECONDS) {
                Known nearest = question.read("1").orElseThrow();
                resolve(nearest, kit.speech.noAnswer(nearest));
            }
            return true;
        }
        if (pursuit == null) {
            return false;
        }
        Status status = pursuit.step();
        if (status == Status.RUNNING) {
            return true;
        }
        String outcome = pursuit.outcome();
        lastOutcome = outcome;
        pursuit = null;
        goal = null;
        leaving = null;
        kit.navigator.reset();
        if (steps.isEmpty()) {
            kit.motor.say(outcome + kit.speech.carryingOn());
        } else {
            if (!outcome.isEmpty()) {
                kit.motor.say(outcome);
            }
            next();
        }
        return true;
    }

    // ---- starting a goal ------------------------------------------------------------------------

    /** Starts the next step that can be started; says why for those that cannot. */
    private void next() {
        while (!steps.isEmpty()) {
            Goal step = steps.poll();
            if (standing(step)) {
                String said = standing(step, true); // the restatement of the instruction said it
                if (!said.isEmpty()) {
                    kit.motor.say(said);
                }
                continue;
            }
            String refused = refusal(step);
            if (refused != null) {
                lastOutcome = refused;
                kit.motor.say(refused + (steps.isEmpty() ? "" : kit.speech.goOnWithTheRest()));
                continue;
            }
            Reference asked = ambiguity(step);
            if (asked != null) {
                Grounding grounding = kit.grounder.ground(asked);
                question = new Question(step, asked.kind(), ((Grounding.Ambiguous) grounding).choices(), kit.memory,
                        kit.grounder, kit.speech);
                askedAt = kit.motor.time();
                goal = step;
                kit.motor.say(question.text());
                return;
            }
            goal = step;
            stepsStarted++;
            pursuit = pursuit(step, null);
            return;
        }
    }

    /** Walks out of the area a rule keeps the agent out of, to the nearest place it may stand. */
    private void leave() {
        Optional<String> rule = kit.forbidden(kit.here());
        Optional<Point2> out = kit.nearestAllowed();
        if (rule.isEmpty() || out.isEmpty()) {
            return;
        }
        leaving = kit.speech.leavingArea(rule.get());
        kit.motor.say(kit.speech.imWhereRuleKeepsMeOut(rule.get()));
        stepsStarted = 0;
        steps.clear();
        pursuit = WalkPursuit.to(kit, out.get(), kit.speech.outOfIt());
    }

    private void resolve(Known chosen, String said) {
        kit.mention(chosen);
        Goal step = question.goal();
        question = null;
        kit.motor.say(said);
        goal = step;
        pursuit = pursuit(step, chosen);
    }

    /** Why the body cannot do this goal at all, or the rules forbid it; null when it may. */
    private String refusal(Goal step) {
        if (step instanceof Collect collect) {
            String unreachable = FruitHeights.refusal(collect.what(), kit.motor.body().gripper(), kit.speech);
            if (unreachable != null) {
                return unreachable;
            }
        }
        return rulebook.refusal(step);
    }

    /** The reference of this goal that fits several landmarks with nothing to choose between them; null when none. */
    private Reference ambiguity(Goal step) {
        Reference reference = null;
        if (step instanceof GoTo goTo) {
            reference = goTo.destination();
        } else if (step instanceof LookAt lookAt) {
            reference = lookAt.target();
        } else if (step instanceof Cross cross && cross.landmark().kind() == Reference.Kind.BRIDGE) {
            reference = cross.landmark();
        }
        if (reference == null || !Grounder.asksWhich(reference.kind())) {
            return null;
        }
        return kit.grounder.ground(reference) instanceof Grounding.Ambiguous ? reference : null;
    }

    /** The pursuit of one goal (never a sequence), with the thing the person chose, if asked. */
    private Pursuit pursuit(Goal step, @Nullable Known chosen) {
        double heading = kit.motor.heading();
        if (step instanceof GoTo goTo) {
            if (goTo.destination().kind() == Reference.Kind.START) {
                return WalkPursuit.to(kit, kit.grounder.start(), kit.speech.backWhereStarted());
            }
            return goTo.destination().kind() == Reference.Kind.PLACE ? new GoingToPlace(kit, goTo.destination())
                    : new GoingTo(kit, goTo.destination(), chosen);
        }
        if (step instanceof Cross cross) {
            if (cross.landmark().kind() == Reference.Kind.FOREST) {
                return throughTheForest();
            }
            return new Crossing(kit, cross.landmark(), chosen);
        }
        if (step instanceof Head head) {
            double way = Turning.heading(head.direction());
            if (head.distance() != null) {
                return Shortfall.walk(kit, way, head.distance(), head.direction().wireName());
            }
            return WalkPursuit.on(kit, way, head.direction().wireName());
        }
        if (step instanceof RelativeMove move) {
            double far = move.distance() != null ? move.distance() : WalkPursuit.FEW_STEPS;
            return switch (move.direction()) {
                case FORWARD -> WalkPursuit.steps(kit, heading, false, far);
                case BACKWARD -> WalkPursuit.steps(kit, heading + Math.PI, true, far);
                case LEFT -> WalkPursuit.steps(kit, heading + Math.PI / 2, false, far);
                case RIGHT -> WalkPursuit.steps(kit, heading - Math.PI / 2, false, far);
            };
        }
        if (step instanceof ComeBack) {
            // after other steps of the same instruction, back to where it was given; else to where the one before was
            return WalkPursuit.to(kit, stepsStarted > 1 ? origin : previousOrigin, kit.speech.back());
        }
        if (step instanceof Collect collect) {
            return new Gathering(kit, collect);
        }
        if (step instanceof Turn turn) {
            return Turning.by(kit, turn.radians());
        }
        if (step instanceof Face face) {
            return Turning.toward(kit, face.direction());
        }
        if (step instanceof LookAt lookAt) {
            return Turning.at(kit, lookAt.target(), chosen);
        }
        if (step instanceof LookFor lookFor) {
            return new Searching(kit, lookFor.what());
        }
        if (step instanceof Explore explore) {
            return new Surveying(kit, explore.area());
        }
        if (step instanceof Follow follow) {
            return new Following(kit, follow.agent());
        }
        if (step instanceof Wait wait) {
            return new Holding(kit, wait.seconds());
        }
        if (step instanceof Stop) {
            return new Holding(kit, Wait.UNTIL_TOLD);
        }
        // CarryOn inside a sequence: the rest is dropped, and the agent is on its own again
        steps.clear();
        return new Holding(kit, 0);
    }

    /** Through the forest: past its nearest known tree, as far again on the other side. */
    private Pursuit throughTheForest() {
        Reference forest = Reference.to(Reference.Kind.FOREST);
        Grounding grounding = kit.grounder.ground(forest);
        if (!(grounding instanceof Grounding.Found found)) {
            return new GoingTo(kit, forest, null);
        }
        Point2 here = kit.here();
        Point2 tree = found.chosen().where();
        Point2 beyond = Bearings.ahead(tree, Bearings.headingTowards(here, tree), Math.max(10, here.distance(tree)));
        return WalkPursuit.to(kit, beyond, kit.speech.throughTheForest());
    }
}
