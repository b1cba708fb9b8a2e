package io.orchard.agents.zoo;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Goal;
import io.orchard.agents.map.KnownFruit;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.function.Predicate;

/**
 * Guppy, the paper's example agent (its Figure 5 gives Guppy's required VRML nodes): an
 * anthropomorphic figure in a blue shirt that collects with its hands, from the ground, from the
 * tables and, stretching its arms up, from most of the trees.
 *
 * <p>Body: radius 0.45, height 1.8, speed 7; hands reaching 0.7 beyond the body, fruit centres
 * from 0 to 2.3 high; sight 45 units over 210 degrees. Model {@code models/Guppy.wrl} (VRML97,
 * with Figure 5's Guppy Transform, GuppyMover and GuppyTSMover) with the joints Neck,
 * LeftShoulder, LeftElbow, RightShoulder, RightElbow, LeftHip, LeftKnee, RightHip, RightKnee and
 * the animations GuppyTSWalk and GuppyTSGrasp.
 *
 * <h2>Architecture: a goal stack</h2>
 * Guppy keeps its intentions on a stack and works on the top one. The bottom of the stack is
 * the standing goal <em>forage</em>, which never ends: it pushes <em>collect</em> for the known
 * fruit that is cheapest to reach, else <em>explore</em>, else <em>wander</em> for a while.
 * A goal that is done or has failed is popped, and the goal below carries on (told how its
 * subgoal went). An instruction pushes <em>obey</em> on top, which lets the controller's errands
 * pursue the instructed goal and is popped when they are done with it (or on "carry on"); Guppy
 * then returns to what was below: its autonomy.
 */
public final class Guppy extends AgentController {

    private static final double SHOULDER_HEIGHT = 1.48;
    private static final double ARM_LENGTH = 0.68;
    private static final int MAX_STEPS_PER_TICK = 3;

    /** A goal on the stack. */
    private interface Task {
        /** One tick's work: DONE or FAILED pops it. */
        Status step();

        /** A subgoal it pushed was popped. */
        default void childFinished(Task child, Status status) {}
    }

    private final Deque<Task> stack = new ArrayDeque<>();
    private Skills skills;
    private Pose pose;

    /** Guppy. */
    public Guppy() {
        this("Guppy");
    }

    /** A Guppy with another name. */
    public Guppy(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder()
                .radius(0.45).height(1.8).speed(7)
                .gripper("hands", 0.7, 0, 2.3)
                .sight(45, Math.toRadians(210))
                .model("models/Guppy.wrl", "Guppy")
                .joints(Pose.figureJoints())
                .walkAnimation(name() + "TSWalk")
                .graspAnimation(name() + "TSGrasp")
                .build();
    }

    @Override
    protected void onRegistered() {
        skills = new Skills(memory(), motor(), planner(), random());
        pose = new Pose(motor());
        skills.harvester.gesture(pose.armsReach(0.6, () -> play(name() + "TSGrasp", 1.5), SHOULDER_HEIGHT,
                ARM_LENGTH, raised -> raised.set("Neck", 0.4)));
        stack.push(new Forage());
    }

    @Override
    protected void onGoal(Goal goal) {
        super.onGoal(goal);
        if (stack.peek() instanceof Persist) {
            stack.pop(); // a person's word comes first; the plan is chosen anew if Guppy gets nowhere again
        }
        if (!(stack.peek() instanceof Obey)) {
            stack.push(new Obey());
        }
    }

    @Override
    protected void decide(Perception perception) {
        pose.update();
        if (skills.persisting(stack.peek() instanceof Obey) && !(stack.peek() instanceof Persist)) {
            while (stack.size() > 1) {
                stack.pop(); // what it was doing got it nowhere: back to the standing goal, which commits
            }
            stack.push(new Persist());
        }
        for (int i = 0; i < MAX_STEPS_PER_TICK; i++) {
            Task top = stack.peek();
            Status status = top.step();
            if (status != Status.RUNNING && stack.size() > 1) {
                stack.pop();
                stack.peek().childFinished(top, status);
                continue;
            }
            if (stack.peek() == top) {
                return; // the top goal acted
            }
        }
    }

    private KnownFruit cheapest(Predicate<KnownFruit> wanted) {
        List<KnownFruit> candidates = skills.harvester.candidates(wanted);
        KnownFruit best = null;
        double bestScore = Double.MAX_VALUE;
        for (KnownFruit fruit : candidates.subList(0, Math.min(3, candidates.size()))) {
            double way = skills.wayTo(fruit);
            if (way == Double.MAX_VALUE) {
                skills.harvester.giveUp(fruit.id());
                continue;
            }
            double score = way / (1 + 0.25 * fruit.points());
            if (score < bestScore) {
                bestScore = score;
                best = fruit;
            }
        }
        return best;
    }

    // ---- the goals ---------------------------------------------------------------------------

    /** The standing goal: collect, else explore, else wander. */
    private final class Forage implements Task {
        @Override
        public Status step() {
            KnownFruit fruit = cheapest(f -> true);
            if (fruit != null) {
                stack.push(new Collect(fruit));
            } else if (!memory().coverage().unseen().isEmpty()) {
                stack.push(new Explore(f -> true));
            } else {
                stack.push(new Wander(time() + 5));
            }
            return Status.RUNNING;
        }
    }

    /** Collect one fruit. */
    private final class Collect implements Task {
        private final KnownFruit fruit;

        Collect(KnownFruit fruit) {
            this.fruit = fruit;
        }

        @Override
        public Status step() {
            return skills.harvester.collect(fruit);
        }
    }

    /** Explore until a fruit that passes {@code found} is known, or all is seen. */
    private final class Explore implements Task {
        private final Predicate<KnownFruit> found;

        Explore(Predicate<KnownFruit> found) {
            this.found = found;
        }

        @Override
        public Status step() {
            if (!skills.harvester.candidates(found).isEmpty()) {
                return Status.DONE;
            }
            return skills.explorer.step(skills.navigator) == Status.DONE ? Status.DONE : Status.RUNNING;
        }
    }

    /** Walk about until a time, or until a fruit is known. */
    private final class Wander implements Task {
        private final double until;

        Wander(double until) {
            this.until = until;
        }

        @Override
        public Status step() {
            if (time() >= until || !skills.harvester.candidates(f -> true).isEmpty()) {
                return Status.DONE;
            }
            skills.wanderer.step(skills.navigator);
            return Status.RUNNING;
        }
    }

    /** Got nowhere: keep to one plan until it is carried out or fails. */
    private final class Persist implements Task {
        @Override
        public Status step() {
            return skills.commitment.step();
        }
    }

    /** An instruction: the errands have Guppy until they are done with it. */
    private final class Obey implements Task {
        @Override
        public Status step() {
            if (pursueInstruction()) {
                return Status.RUNNING;
            }
            skills.navigator.reset(); // its last route is stale
            return Status.DONE;
        }
    }
}
