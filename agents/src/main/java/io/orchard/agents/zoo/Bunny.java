package io.orchard.agents.zoo;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.behaviour.Steering;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.Obstruction;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.Point2;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The paper's four-legged bunny: small and quick, it eats with its mouth and so reaches only what
 * lies on the ground.
 *
 * <p>Body: radius 0.35, height 0.6, speed 12; the mouth reaching 0.3 beyond the body, fruit
 * centres from 0 to 0.5 high; sight 35 units over 320 degrees, as a hare's eyes see. Model
 * {@code models/Bunny.x3d} with the joints FrontLeftLeg, FrontRightLeg, BackLeftLeg,
 * BackRightLeg, Head, LeftEar and RightEar, and the animations BunnyTSWalk (a hop) and
 * BunnyTSGrasp.
 *
 * <h2>Architecture: purely reactive</h2>
 * No map, no plan: each tick the bunny maps what it perceives now straight to an action, by fixed
 * rules tried in order (stimulus, response):
 * <ol>
 *   <li>a fruit on the ground within reach of its mouth: face it and eat;
 *   <li>a fruit on the ground in view: hop towards the nearest;
 *   <li>nothing to eat in view for a while and a bridge in view: hop across it;
 *   <li>otherwise: hop on in its current direction, turning now and then.
 * </ol>
 * An instruction overrides the rules while it lasts: the controller's errands pursue it with the
 * map the controller keeps (the bunny's own rules keep none), and the rules take over again once
 * it is done. Every hop is steered around the trunks, tables, agents and river bank in view
 * ({@link Steering}). Its only state is a handful of reflex timers: a heading it was just refused
 * (by the castle, which it cannot see) is shunned for a few seconds, a fruit it failed to eat or
 * could not get nearer to (across the river) is ignored for a while, and a bridge crossing, once
 * begun, is finished.
 */
public final class Bunny extends AgentController {

    private static final double HOP = 2;
    private static final double HUNGRY_SECONDS = 8;
    private static final double SHUN_SECONDS = 5;
    private static final double BORED_SECONDS = 4;

    private Steering steering;
    private Skills skills;
    private double wanderHeading = Double.NaN;
    private double turnAt;
    private double lastMeal;
    private double lastFoodSeen;
    private String crossing;
    private String craving;
    private double closest;
    private double cravingSince;
    private Point2 farBank;
    private final Map<String, Double> refused = new HashMap<>();
    private MoveStatus reflexHandled;
    private GraspStatus graspHandled;

    /** A bunny called Bunny. */
    public Bunny() {
        this("Bunny");
    }

    /** A bunny with another name. */
    public Bunny(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder()
                .radius(0.35).height(0.6).speed(12)
                .gripper("mouth", 0.3, 0, 0.5)
                .sight(35, Math.toRadians(320))
                .model("models/Bunny.x3d", "Bunny")
                .joints("FrontLeftLeg", "FrontRightLeg", "BackLeftLeg", "BackRightLeg", "Head", "LeftEar", "RightEar")
                .walkAnimation(name() + "TSWalk")
                .graspAnimation(name() + "TSGrasp")
                .build();
    }

    @Override
    protected void onRegistered() {
        steering = new Steering(bodyInForce().radius(), welcome().bounds());
        skills = new Skills(memory(), motor(), planner(), random());
        skills.harvester.gesture(fruit -> play(name() + "TSGrasp", 1.5));
    }

    @Override
    protected void decide(Perception perception) {
        reflexes();
        boolean persisting = skills.persisting(instructed());
        if (pursueInstruction()) {
            return;
        }
        if (persisting) {
            crossing = null;
            skills.commitment.step();
            return;
        }
        Point2 here = perception.ground();
        Optional<PerceivedFruit> food = perception.nearestFruit(this::edible);
        if (food.isPresent()) {
            lastFoodSeen = time();
            crossing = null;
            PerceivedFruit fruit = food.get();
            double reach = bodyInForce().radius() + bodyInForce().gripper().reach() + fruit.radius();
            double distance = here.distance(fruit.position().onGround());
            if (losingInterest(fruit, distance)) {
                return;
            }
            if (distance <= reach - 0.05) {
                eat(fruit, here);
            } else {
                hopTowards(perception, Bearings.headingTowards(here, fruit.position().onGround()),
                        Math.min(HOP, distance - (reach - 0.2)));
            }
            return;
        }
        if (crossing != null || time() - lastFoodSeen > HUNGRY_SECONDS) {
            if (cross(perception)) {
                return;
            }
        }
        wander(perception);
    }

    /**
     * Habituation: a fruit the bunny hops towards without getting nearer (it lies across the
     * river, or behind a table it keeps bumping around) stops attracting it for a while.
     */
    private boolean losingInterest(PerceivedFruit fruit, double distance) {
        if (!fruit.id().equals(craving) || distance < closest - 0.5) {
            craving = fruit.id();
            closest = distance;
            cravingSince = time();
            return false;
        }
        if (time() - cravingSince > BORED_SECONDS) {
            refused.put(fruit.id(), time() + 30);
            craving = null;
            return true;
        }
        return false;
    }

    /** Ear twitches and the shunned headings: the bunny's only memory, a few seconds long. */
    private void reflexes() {
        MoveStatus last = motor().lastMove();
        if (last != null && last != reflexHandled && last.rejected() && Obstruction.of(last.reason()).isObstacle()) {
            reflexHandled = last;
            double refusedHeading = Bearings.headingTowards(last.from(), last.to());
            steering.avoid(refusedHeading, Math.toRadians(60), time() + SHUN_SECONDS);
            wanderHeading = Bearings.normalise(refusedHeading + Math.PI * (0.6 + 0.8 * random().nextDouble()));
        }
        GraspStatus grasp = motor().lastGrasp();
        if (grasp != null && grasp != graspHandled && grasp.answered()) {
            graspHandled = grasp;
            if (grasp.success()) {
                lastMeal = time();
                setJoint("LeftEar", Pose.pitch(0.6));
                setJoint("RightEar", Pose.pitch(0.6));
            } else {
                refused.put(grasp.fruit(), time() + 20);
            }
        }
        if (lastMeal > 0 && time() - lastMeal > 1 && time() - lastMeal < 1.06) {
            setJoint("LeftEar", Pose.pitch(0));
            setJoint("RightEar", Pose.pitch(0));
        }
    }

    private boolean edible(PerceivedFruit fruit) {
        Double until = refused.get(fruit.id());
        if (until != null && until > time()) {
            return false;
        }
        if (!memory().fruit(fruit.id()).map(memory().conduct()::allows).orElse(true)) {
            return false; // a person's rule: "leave the bananas"
        }
        double y = fruit.position().y();
        return y >= bodyInForce().gripper().minHeight() + 0.006 && y <= bodyInForce().gripper().maxHeight() - 0.006;
    }

    private void eat(PerceivedFruit fruit, Point2 here) {
        face(fruit.position().onGround());
        play(name() + "TSGrasp", 1.5);
        grasp(fruit.id());
    }

    private void hopTowards(Perception perception, double wanted, double length) {
        if (length < 0.05) {
            return;
        }
        steering.step(perception.message(), perception.landmarks(), wanted, length, time())
                .ifPresent(this::hop);
    }

    /** Sends the hop unless the current one already goes that way. */
    private void hop(Point2 end) {
        Point2 here = position();
        MoveStatus last = motor().lastMove();
        if (motor().walking() && last != null && !last.rejected() && !last.blocked()
                && last.to().distance(here) > 0.6
                && Math.abs(Bearings.normalise(Bearings.headingTowards(here, last.to())
                        - Bearings.headingTowards(here, end))) < Math.toRadians(10)) {
            return;
        }
        face(end);
        moveTo(end);
    }

    /** Hops onto a bridge in view and across it; true while doing so. */
    private boolean cross(Perception perception) {
        Point2 here = perception.ground();
        for (PerceivedBridge bridge : perception.bridges()) {
            if (crossing != null && !bridge.id().equals(crossing)) {
                continue;
            }
            Point2 a = perception.toWorld(bridge.entryA());
            Point2 b = perception.toWorld(bridge.entryB());
            if (crossing == null) {
                Point2 far = here.distance(a) <= here.distance(b) ? b : a;
                Point2 near = far == a ? b : a;
                double length = near.distance(far);
                Point2 beyond = new Point2(far.x() + (far.x() - near.x()) / length * 3,
                        far.z() + (far.z() - near.z()) / length * 3);
                if (memory().conduct().forbids(beyond)) {
                    continue; // a person's rule keeps it on this bank
                }
                crossing = bridge.id();
                farBank = beyond;
            }
            Point2 near = here.distance(a) <= here.distance(b) ? a : b;
            boolean onIt = distanceToSegment(here, a, b) < bridge.width() / 2 - bodyInForce().radius();
            Point2 aim = onIt || here.distance(near) < 1 ? farBank : near;
            if (here.distance(farBank) < 1) {
                crossing = null;
                lastFoodSeen = time();
                return false;
            }
            hopTowards(perception, Bearings.headingTowards(here, aim), Math.min(HOP, here.distance(aim)));
            return true;
        }
        crossing = null;
        return false;
    }

    private void wander(Perception perception) {
        if (Double.isNaN(wanderHeading) || time() >= turnAt) {
            wanderHeading = Double.isNaN(wanderHeading) ? perception.heading()
                    : Bearings.normalise(wanderHeading + random().nextGaussian() * 0.8);
            turnAt = time() + 3 + 4 * random().nextDouble();
        }
        Optional<Point2> step = steering.step(perception.message(), perception.landmarks(), wanderHeading, HOP, time());
        if (step.isPresent()) {
            Point2 end = step.get();
            double went = Bearings.headingTowards(perception.ground(), end);
            if (Math.abs(Bearings.normalise(went - wanderHeading)) > Math.toRadians(40)) {
                wanderHeading = went; // bounced off something: go on that way
            }
            hop(end);
        } else {
            wanderHeading = Bearings.normalise(wanderHeading + Math.PI);
        }
    }

    private static double distanceToSegment(Point2 p, Point2 a, Point2 b) {
        double dx = b.x() - a.x();
        double dz = b.z() - a.z();
        double lengthSq = dx * dx + dz * dz;
        double t = lengthSq == 0 ? 0 : Math.max(0, Math.min(1, ((p.x() - a.x()) * dx + (p.z() - a.z()) * dz) / lengthSq));
        return Math.hypot(a.x() + t * dx - p.x(), a.z() + t * dz - p.z());
    }
}
