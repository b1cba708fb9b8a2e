package io.orchard.agents;

import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.StopAnimationMessage;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;

/**
 * The body's walk animation ({@link AgentBody#walkAnimation()}), looping while the agent walks,
 * unless another animation has the joints: one played once pauses it until it is over. A stopped
 * animation freezes where it is, so when the walk ends the joints go back to their neutral pose,
 * unless the agent posed them itself during that tick.
 */
final class WalkAnimation {

    private static final Rotation NEUTRAL = new Rotation(new Vec3(1, 0, 0), 0);

    private final String agent;
    private final Session session;
    private final Situation situation;
    private boolean playing;
    private double busyUntil = Double.NEGATIVE_INFINITY;
    private long posedTick = -1;

    WalkAnimation(String agent, Session session, Situation situation) {
        this.agent = agent;
        this.session = session;
        this.situation = situation;
    }

    /** The agent posed a joint itself in this tick. */
    void posed(long tick) {
        posedTick = tick;
    }

    /** Another animation starts in this tick and has the joints until {@code until}: the walk pauses. */
    void pause(long tick, double until) {
        posedTick = tick;
        if (playing) {
            stop(false);
        }
        busyUntil = Math.max(busyUntil, until);
    }

    /** At the end of a turn: starts or stops the walk animation as the agent walks or stands. */
    void update(boolean walking, long tick, double time) {
        String walk = situation.plan().walkAnimation();
        if (walk == null) {
            return;
        }
        if (playing && !walking) {
            stop(posedTick != tick);
        } else if (!playing && walking && time >= busyUntil) {
            session.send(s -> new StartAnimationMessage(s, agent, walk, true));
            playing = true;
        }
    }

    private void stop(boolean toNeutral) {
        AgentBody plan = situation.plan();
        session.send(s -> new StopAnimationMessage(s, agent, plan.walkAnimation()));
        playing = false;
        if (toNeutral) {
            for (String joint : plan.joints()) {
                session.send(s -> new SetJointRotationMessage(s, agent, joint, NEUTRAL));
            }
        }
    }
}
