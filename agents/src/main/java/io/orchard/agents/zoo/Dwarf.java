package io.orchard.agents.zoo;

import io.orchard.agents.AgentBody;
import io.orchard.agents.AgentController;
import io.orchard.agents.Perception;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Stop;
import io.orchard.agents.language.Wait;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.SeenAgent;
import io.orchard.protocol.value.Point2;
import java.util.List;

/**
 * The paper's anthropomorphic dwarf: short, bearded, red-hatted; it collects fruit with its hands,
 * from the ground, from tables and from the lowest branches.
 *
 * <p>Body: radius 0.4, height 1.2, speed 6; hands reaching 0.6 beyond the body, fruit centres
 * from 0 to 1.6 high; sight 40 units over 200 degrees. Model {@code models/Dwarf.x3d} with the
 * joints Neck, LeftShoulder, LeftElbow, RightShoulder, RightElbow, LeftHip, LeftKnee, RightHip,
 * RightKnee and the animations DwarfTSWalk and DwarfTSGrasp.
 *
 * <h2>Architecture: subsumption layers</h2>
 * After Brooks: a stack of layers of competence, each a complete small behaviour that runs
 * every tick; a layer that has something to do takes control and suppresses every layer below
 * it. From the top:
 * <ol>
 *   <li><b>reflex</b>: when another agent is about to bump into it, or the server cut its move
 *       short, it steps aside for a moment (unless it was told to stop or wait);
 *   <li><b>obey</b>: while an instruction is pending, the controller's errands carry it out;
 *   <li><b>grab</b>: a fruit within reach of its hands is grasped at once;
 *   <li><b>forage</b>: walks to the nearest known fruit it can reach;
 *   <li><b>explore</b>: heads for what it has not seen;
 *   <li><b>wander</b>: walks about.
 * </ol>
 * No layer knows the others; there is no plan beyond the layer in control, and the arbitration is
 * fixed by the order of the layers.
 */
public final class Dwarf extends AgentController {

    private static final double SHOULDER_HEIGHT = 0.86;
    private static final double ARM_LENGTH = 0.44;
    private static final double REFLEX_SECONDS = 0.6;

    /** A layer of competence: acts and returns true when it takes control this tick. */
    private interface Layer {
        boolean act();
    }

    private final List<Layer> layers = List.of(this::reflex, this::obey, this::persist, this::grab, this::forage,
            this::explore, this::wander);
    private Skills skills;
    private Pose pose;
    private KnownFruit target;
    private double reflexUntil = Double.NEGATIVE_INFINITY;
    private Point2 aside;
    private MoveStatus reflexHandled;
    private boolean persisting;

    /** A dwarf called Dwarf. */
    public Dwarf() {
        this("Dwarf");
    }

    /** A dwarf with another name. */
    public Dwarf(String name) {
        super(name);
    }

    @Override
    protected AgentBody body() {
        return AgentBody.builder()
                .radius(0.4).height(1.2).speed(6)
                .gripper("hands", 0.6, 0, 1.6)
                .sight(40, Math.toRadians(200))
                .model("models/Dwarf.x3d", "Dwarf")
                .joints(Pose.figureJoints())
                .walkAnimation(name() + "TSWalk")
                .graspAnimation(name() + "TSGrasp")
                .build();
    }

    @Override
    protected void onRegistered() {
        skills = new Skills(memory(), motor(), planner(), random());
        pose = new Pose(motor());
        skills.harvester.gesture(pose.armsReach(0.45, () -> play(name() + "TSGrasp", 1.5), SHOULDER_HEIGHT,
                ARM_LENGTH, raised -> raised.set("Neck", 0.3)));
    }

    @Override
    protected void decide(Perception perception) {
        pose.update();
        persisting = skills.persisting(instructed());
        for (Layer layer : layers) {
            if (layer.act()) {
                return;
            }
        }
    }

    // ---- the layers, from the top --------------------------------------------------------------

    private boolean reflex() {
        if (errands().goal() instanceof Stop || errands().goal() instanceof Wait) {
            return false; // told to stand still, it stands its ground
        }
        MoveStatus last = motor().lastMove();
        boolean bumped = last != null && last.blocked() && last != reflexHandled;
        if (bumped) {
            reflexHandled = last;
        }
        SeenAgent close = closeAhead();
        if ((bumped || close != null) && time() >= reflexUntil) {
            aside = sidestep(close);
            reflexUntil = aside == null ? reflexUntil : time() + REFLEX_SECONDS;
            if (aside != null) {
                motor().moveTo(aside, true);
            }
        }
        return time() < reflexUntil;
    }

    private boolean obey() {
        if (!pursueInstruction()) {
            return false;
        }
        target = null; // chosen again afterwards, from what it knows then
        return true;
    }

    private boolean persist() {
        if (!persisting) {
            return false;
        }
        target = null;
        skills.commitment.step();
        return true;
    }

    private boolean grab() {
        for (KnownFruit fruit : skills.harvester.candidates(f -> skills.harvester.inReach(f, position()))) {
            target = fruit;
            skills.harvester.collect(fruit);
            return true;
        }
        return false;
    }

    private boolean forage() {
        if (target != null && (memory().gone(target.id()) || skills.harvester.givenUp(target.id()))
                && !target.id().equals(skills.harvester.current())) {
            target = null;
        }
        if (target == null) {
            for (KnownFruit fruit : skills.harvester.candidates(f -> true)) {
                if (skills.wayTo(fruit) < Double.MAX_VALUE) {
                    target = fruit;
                    break;
                }
                skills.harvester.giveUp(fruit.id());
            }
        }
        if (target == null) {
            return false;
        }
        if (skills.harvester.collect(target) != Status.RUNNING) {
            target = null;
        }
        return true;
    }

    private boolean explore() {
        return skills.explorer.step(skills.navigator) == Status.RUNNING;
    }

    private boolean wander() {
        skills.wanderer.step(skills.navigator);
        return true;
    }

    // ---- the reflex's senses -------------------------------------------------------------------

    /** Another agent right in front, closer than a stride. */
    private SeenAgent closeAhead() {
        Point2 here = position();
        for (SeenAgent other : memory().agents()) {
            double gap = here.distance(other.position()) - other.radius() - bodyInForce().radius();
            if (gap < 0.5 && Math.abs(Bearings.bearing(here, heading(), other.position())) < Math.PI / 3
                    && motor().walking()) {
                return other;
            }
        }
        return null;
    }

    /** A free point a stride to the side, away from the other agent; null if there is none. */
    private Point2 sidestep(SeenAgent other) {
        Point2 here = position();
        double away = other == null ? heading() : Bearings.headingTowards(other.position(), here);
        for (double turn : new double[] {Math.PI / 2, -Math.PI / 2, Math.PI * 3 / 4, -Math.PI * 3 / 4, 0}) {
            Point2 p = Bearings.ahead(here, away + turn * (random().nextBoolean() ? 1 : -1), 1.5);
            if (skills.planner.clear(here, p, 0.15, List.of())) {
                return p;
            }
        }
        return null;
    }
}
