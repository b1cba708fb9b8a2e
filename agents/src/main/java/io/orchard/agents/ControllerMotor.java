package io.orchard.agents;

import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.StopAnimationMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Rotation;
import java.util.Optional;

/**
 * The agent's actions, for its controller's methods and, as a {@link Motor}, for its behaviours:
 * each sends the paper's message and notes what it started, the latest move and grasp
 * ({@link MoveTracker}, {@link GraspTracker}), the heading after a turn and the joints posed this
 * tick, which the {@link WalkAnimation} leaves alone. It holds every behaviour to the rules a person
 * set ({@link io.orchard.agents.map.Conduct}): a walk into an area the agent must keep out of ends at
 * its edge, and a grasp of fruit it must leave is not sent but fails at once, with the rule as the
 * reason.
 */
final class ControllerMotor implements Motor {

    private final String agent;
    private final Session session;
    private final Situation situation;
    private final Turns turns;
    private final Tally tally;
    private final MoveTracker moves = new MoveTracker();
    private final GraspTracker grasps = new GraspTracker();
    private final WalkAnimation walkAnimation;

    ControllerMotor(String agent, Session session, Situation situation, Turns turns, Tally tally) {
        this.agent = agent;
        this.session = session;
        this.situation = situation;
        this.turns = turns;
        this.tally = tally;
        this.walkAnimation = new WalkAnimation(agent, session, situation);
    }

    @Override
    public Point2 position() {
        return situation.position();
    }

    @Override
    public double heading() {
        return situation.heading();
    }

    @Override
    public long tick() {
        return turns.tick();
    }

    @Override
    public double time() {
        return turns.time();
    }

    @Override
    public Body body() {
        return situation.body();
    }

    @Override
    public void moveTo(Point2 to, boolean face) {
        if (face) {
            face(to);
        }
        moveTo(to);
    }

    /** Walks straight from where the agent stands to {@code to}, as far as the rules let it. */
    void moveTo(Point2 to) {
        Point2 from = situation.position();
        if (situation.inWorld()) {
            to = situation.memory().conduct().cut(from, to);
        }
        Point2 end = to;
        long seq = session.send(s -> new MoveMessage(s, agent, from.at(0), end.at(0)));
        moves.sent(seq, from, end, turns.tick());
        tally.movesSent++;
    }

    @Override
    public void turnTo(double heading) {
        session.send(s -> new SetRotationMessage(s, agent, Rotation.heading(heading)));
        situation.turned(heading);
    }

    /** Turns to face a point, unless the agent stands on it. */
    void face(Point2 point) {
        Point2 here = situation.position();
        if (point.distance(here) > 1e-6) {
            turnTo(Bearings.headingTowards(here, point));
        }
    }

    @Override
    public void halt() {
        moveTo(situation.position());
    }

    @Override
    public boolean walking() {
        return moves.walking();
    }

    @Override
    public MoveStatus lastMove() {
        return moves.last();
    }

    @Override
    public void grasp(String fruitId) {
        if (situation.inWorld()) {
            Optional<String> rule = situation.memory().fruit(fruitId).flatMap(situation.memory().conduct()::ruleAgainst);
            if (rule.isPresent()) {
                grasps.refused(fruitId, turns.tick(), rule.get());
                return;
            }
        }
        long seq = session.send(s -> new GraspRequestMessage(s, agent, fruitId));
        grasps.sent(seq, fruitId, turns.tick());
        tally.graspsSent++;
    }

    @Override
    public GraspStatus lastGrasp() {
        return grasps.last();
    }

    @Override
    public void setJoint(String joint, Rotation rotation) {
        walkAnimation.posed(turns.tick());
        session.send(s -> new SetJointRotationMessage(s, agent, joint, rotation));
    }

    @Override
    public void startAnimation(String timeSensor, boolean loop) {
        session.send(s -> new StartAnimationMessage(s, agent, timeSensor, loop));
    }

    @Override
    public void stopAnimation(String timeSensor) {
        session.send(s -> new StopAnimationMessage(s, agent, timeSensor));
    }

    @Override
    public void play(String timeSensor, double seconds) {
        walkAnimation.pause(turns.tick(), turns.time() + seconds);
        startAnimation(timeSensor, false);
    }

    @Override
    public void say(String text) {
        String line = text.length() > Checks.MAX_TEXT ? text.substring(0, Checks.MAX_TEXT) : text;
        session.send(s -> new SayMessage(s, agent, line));
    }

    /** Asks for a perception at the start of the next tick and then every {@code every} ticks (0: only the next). */
    void requestPerception(int every) {
        if (every < 0) {
            throw new IllegalArgumentException("every must not be negative, was " + every);
        }
        session.send(s -> new PerceptionRequestMessage(s, agent, every));
        turns.requested(every);
    }

    // ---- what the controller's loop tells it -------------------------------------------------

    /** The server answered a move. */
    void answered(ActionResultMessage result, MoveMessage move) {
        moves.answered(result, move, situation.memory(), turns.tickRate());
    }

    /** The server answered a grasp. */
    void answered(GraspResultMessage result) {
        grasps.answered(result);
    }

    /** A turn is taken, on a perception or without one: the walk may be over. */
    void turnTaken(boolean perceived) {
        moves.update(turns.tick(), turns.time(), perceived, situation.stoodStill());
    }

    /** The agent has decided its turn: the walk animation follows whether it walks. */
    void decided() {
        walkAnimation.update(moves.walkingSomewhere(), turns.tick(), turns.time());
    }
}
