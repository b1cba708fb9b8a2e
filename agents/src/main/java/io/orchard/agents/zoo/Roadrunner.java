package io.orchard.agents.zoo;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.agents.behaviour.Harvester;
import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.Stop;
import io.orchard.agents.map.KnownFruit;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.value.FruitKind;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * The paper's Roadrunner (its Figure 3): a two-legged animat that walks in any direction, jumps,
 * kneels, and picks fruit up with its beak. Each leg has three joints; the neck has four, enough
 * to bring the head down to the ground; the beak has two parts that open and close.
 *
 * <p>Body: radius 0.4, height 1.6, speed 15; the beak reaching 0.9 beyond the body, fruit centres
 * from 0 to 3.2 high (it jumps for the highest); sight 50 units over 300 degrees, as a bird's
 * eyes see. Model {@code models/Roadrunner.x3d} with the joints LeftHip, LeftKnee, LeftAnkle,
 * RightHip, RightKnee, RightAnkle, Neck1 to Neck4, UpperBeak and LowerBeak, and the animations
 * RoadrunnerTSWalk, RoadrunnerTSGrasp, RoadrunnerTSJump and RoadrunnerTSKneel.
 *
 * <h2>Architecture: a behaviour-based arbiter with utility scores</h2>
 * Independent behaviours each score, every tick, how useful they would be now, between 0 and 1;
 * an arbiter gives control to the highest score, with a small bonus for the behaviour in control
 * so that it does not dither between near-equal choices. The behaviours:
 * <ul>
 *   <li><b>obey</b>: 2, above all others, while an instruction is pending (the controller's errands
 *       carry it out);
 *   <li><b>peck</b>: for the best known fruit, more for more points and less the longer the run
 *       there ({@code 0.5 + 0.5 * points / 3 * exp(-seconds / 20)});
 *   <li><b>explore</b>: {@code 0.45} times the square root of the share of the world not yet seen;
 *   <li><b>wander</b>: 0.05, when nothing else is worth doing.
 * </ul>
 * It walks in any direction: it keeps its heading while the way lies within 100 degrees of it
 * (stepping sideways), and turns only to run the other way or to face the fruit it pecks.
 */
public final class Roadrunner extends AgentController {

    private static final double HYSTERESIS = 0.1;
    private static final double RESCORE_SECONDS = 1;

    /** A behaviour that scores its usefulness and acts when chosen. */
    private interface Behaviour {
        double utility();

        void act();
    }

    private final Behaviour obey = new Behaviour() {
        @Override
        public double utility() {
            return instructed() ? 2 : 0; // above every other score, hysteresis included: a person asked
        }

        @Override
        public void act() {
            pursueInstruction();
        }
    };

    private final Behaviour peck = new Behaviour() {
        @Override
        public double utility() {
            if (time() - scoredAt >= RESCORE_SECONDS || prey == null
                    || (memory().gone(prey.id()) && !prey.id().equals(skills.harvester.current()))
                    || skills.harvester.givenUp(prey.id())) {
                choosePrey();
            }
            return prey == null ? 0 : preyScore;
        }

        @Override
        public void act() {
            Status status = skills.harvester.collect(prey);
            if (status != Status.RUNNING) {
                prey = null;
            }
        }
    };

    private final Behaviour explore = new Behaviour() {
        @Override
        public double utility() {
            double unseen = 1 - memory().coverage().fractionSeen();
            return explored ? 0 : 0.45 * Math.sqrt(Math.max(0, unseen));
        }

        @Override
        public void act() {
            explored = skills.explorer.step(skills.navigator) == Status.DONE;
        }
    };

    private final Behaviour wander = new Behaviour() {
        @Override
        public double utility() {
            return 0.05;
        }

        @Override
        public void act() {
            skills.wanderer.step(skills.navigator);
        }
    };

    private final Behaviour persist = new Behaviour() {
        @Override
        public double utility() {
            return persisting ? 1.5 : 0; // got nowhere: above anything it chose by itself, below a person's word
        }

        @Override
        public void act() {
            skills.commitment.step();
        }
    };

    private final List<Behaviour> behaviours = List.of(obey, persist, peck, explore, wander);
    private Skills skills;
    private Pose pose;
    private Behaviour active;
    private KnownFruit prey;
    private double preyScore;
    private double scoredAt = Double.NEGATIVE_INFINITY;
    private boolean explored;
    private boolean persisting;

    /** A roadrunner called Roadrunner. */
    public Roadrunner() {
        this("Roadrunner");
    }

    /** A roadrunner with another name. */
    public Roadrunner(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder()
                .radius(0.4).height(1.6).speed(15)
                .gripper("mouth", 0.9, 0, 3.2)
                .sight(50, Math.toRadians(300))
                .model("models/Roadrunner.x3d", "Roadrunner")
                .joints("LeftHip", "LeftKnee", "LeftAnkle", "RightHip", "RightKnee", "RightAnkle",
                        "Neck1", "Neck2", "Neck3", "Neck4", "UpperBeak", "LowerBeak")
                .timeSensors(name() + "TSJump", name() + "TSKneel")
                .walkAnimation(name() + "TSWalk")
                .graspAnimation(name() + "TSGrasp")
                .build();
    }

    @Override
    protected void onRegistered() {
        skills = new Skills(memory(), motor(), planner(), random());
        skills.navigator.faceBeyond(Math.toRadians(100));
        pose = new Pose(motor());
        skills.harvester.gesture(new Harvester.Gesture() {
            @Override
            public void reach(KnownFruit fruit) {
                if (fruit.height() < 0.5) {
                    play(name() + "TSGrasp", 1.5);
                } else if (fruit.height() <= 1.4) {
                    double f = Math.max(0, Math.min(1, (1.35 - fruit.height()) / 1.26));
                    pose.set("Neck1", -1.29 * f).set("Neck2", -0.79 * f).set("Neck3", -0.18 * f)
                            .set("Neck4", 0.79 * f).set("UpperBeak", 0.4).set("LowerBeak", -0.5).holdFor(0.8);
                } else {
                    play(name() + "TSJump", 1);
                    pose.set("UpperBeak", 0.4).set("LowerBeak", -0.5).holdFor(0.6);
                }
            }
        });
    }

    @Override
    protected void onGoal(Goal goal) {
        super.onGoal(goal);
        if (goal instanceof Stop) {
            play(name() + "TSKneel", 2); // it kneels to wait
        }
    }

    @Override
    protected void onGraspResult(GraspResultMessage result) {
        if (result.success() && result.points() == FruitKind.COCONUT.points()) {
            play(name() + "TSJump", 1); // a coconut is worth a jump for joy
        }
    }

    @Override
    protected void decide(Perception perception) {
        pose.update();
        persisting = skills.persisting(instructed());
        Behaviour best = null;
        double bestScore = -1;
        for (Behaviour behaviour : behaviours) {
            double utility = behaviour.utility();
            // The bonus keeps a useful behaviour in control, never one that has nothing left to do.
            double score = utility + (behaviour == active && utility > 0 ? HYSTERESIS : 0);
            if (score > bestScore) {
                bestScore = score;
                best = behaviour;
            }
        }
        if (best != active) {
            skills.navigator.reset();
            skills.wanderer.reset();
            active = best;
        }
        active.act();
    }

    /** The fruit worth most for the run: points, discounted by the seconds it takes to get there. */
    private void choosePrey() {
        scoredAt = time();
        double speed = bodyInForce().maxSpeed();
        List<KnownFruit> candidates = new ArrayList<>(skills.harvester.candidates(f -> true));
        candidates = candidates.subList(0, Math.min(5, candidates.size()));
        candidates.sort(Comparator.comparingDouble(f -> -score(f, position().distance(f.ground()) * 1.2 / speed)));
        KnownFruit best = null;
        double bestScore = 0;
        for (KnownFruit fruit : candidates.subList(0, Math.min(3, candidates.size()))) {
            double way = skills.wayTo(fruit);
            if (way == Double.MAX_VALUE) {
                skills.harvester.giveUp(fruit.id());
                continue;
            }
            double score = score(fruit, way / speed) + (prey != null && fruit.id().equals(prey.id()) ? 0.05 : 0);
            if (score > bestScore) {
                bestScore = score;
                best = fruit;
            }
        }
        prey = best;
        preyScore = best == null ? 0 : bestScore;
    }

    private static double score(KnownFruit fruit, double runSeconds) {
        return 0.5 + 0.5 * fruit.points() / 3.0 * Math.exp(-(runSeconds + 1) / 20);
    }
}
