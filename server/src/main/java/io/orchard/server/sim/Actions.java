package io.orchard.server.sim;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.AgentRotatedMessage;
import io.orchard.protocol.message.AnimationStartedMessage;
import io.orchard.protocol.message.AnimationStoppedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.JointRotatedMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.StopAnimationMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.MoveResult;
import io.orchard.server.world.World;

/**
 * Checks an agent's actions against the world and carries out the valid ones. Every action is
 * answered with an {@link ActionResultMessage}; a rejected action changes nothing and no viewer
 * hears of it.
 */
final class Actions {

    /** How far {@code from} of a move may be from where the server has the agent. */
    static final double FROM_TOLERANCE = 0.5;

    private final Simulation sim;
    private final World world;
    private final Walking walking;

    Actions(Simulation sim, World world, Walking walking) {
        this.sim = sim;
        this.world = world;
        this.walking = walking;
    }

    /** The agent an action names. */
    String agentOf(ClientMessage message) {
        if (message instanceof MoveMessage m) {
            return m.agent();
        } else if (message instanceof SetRotationMessage m) {
            return m.agent();
        } else if (message instanceof SetJointRotationMessage m) {
            return m.agent();
        } else if (message instanceof StartAnimationMessage m) {
            return m.agent();
        } else if (message instanceof StopAnimationMessage m) {
            return m.agent();
        } else if (message instanceof RegisterJointMessage m) {
            return m.agent();
        } else if (message instanceof RegisterTimeSensorMessage m) {
            return m.agent();
        } else if (message instanceof UnregisterMessage m) {
            return m.agent();
        } else if (message instanceof PerceptionRequestMessage m) {
            return m.agent();
        }
        throw new IllegalArgumentException("not an agent action: " + message);
    }

    void apply(Agent agent, ClientMessage message, boolean running, double time) {
        long tick = sim.tick();
        if (message instanceof RegisterJointMessage m) {
            agent.joints.add(m.joint());
            accept(agent, m.seq(), message);
        } else if (message instanceof RegisterTimeSensorMessage m) {
            agent.timeSensors.add(m.timeSensor());
            accept(agent, m.seq(), message);
        } else if (message instanceof UnregisterMessage m) {
            accept(agent, m.seq(), message);
            sim.removeAgent(agent, "unregistered");
        } else if (message instanceof PerceptionRequestMessage m) {
            agent.perceptionRequested = true;
            agent.perceptionEvery = m.every();
            agent.nextPerceptionTick = tick + 1 + m.every();
            accept(agent, m.seq(), message);
        } else if (message instanceof SetJointRotationMessage m) {
            if (!agent.joints.contains(m.joint())) {
                reject(agent, m.seq(), message, "joint " + m.joint() + " not registered");
            } else {
                accept(agent, m.seq(), message);
                sim.broadcast(new JointRotatedMessage(tick, agent.name, m.joint(), m.rotation()), Audience.VIEWERS);
            }
        } else if (message instanceof StartAnimationMessage m) {
            if (!agent.timeSensors.contains(m.timeSensor())) {
                reject(agent, m.seq(), message, "time sensor " + m.timeSensor() + " not registered");
            } else {
                accept(agent, m.seq(), message);
                sim.broadcast(new AnimationStartedMessage(tick, agent.name, m.timeSensor(), m.loop()), Audience.VIEWERS);
            }
        } else if (message instanceof StopAnimationMessage m) {
            if (!agent.timeSensors.contains(m.timeSensor())) {
                reject(agent, m.seq(), message, "time sensor " + m.timeSensor() + " not registered");
            } else {
                accept(agent, m.seq(), message);
                sim.broadcast(new AnimationStoppedMessage(tick, agent.name, m.timeSensor()), Audience.VIEWERS);
            }
        } else if (message instanceof SetRotationMessage m) {
            if (!m.rotation().isAboutUpAxis()) {
                reject(agent, m.seq(), message, "an agent turns only about the up axis (0, 1, 0), axis was "
                        + m.rotation().axis());
            } else if (!running) {
                notRunning(agent, m.seq(), message);
            } else {
                agent.heading = Angles.normalise(m.rotation().headingAngle());
                accept(agent, m.seq(), message);
                sim.broadcast(new AgentRotatedMessage(tick, agent.name, m.rotation()), Audience.VIEWERS);
            }
        } else if (message instanceof MoveMessage m) {
            move(agent, m, running, time);
        }
    }

    private void move(Agent agent, MoveMessage move, boolean running, double time) {
        if (!running) {
            notRunning(agent, move.seq(), move);
            return;
        }
        Vec3 here = agent.position;
        if (here.groundDistance(move.from()) > FROM_TOLERANCE) {
            reject(agent, move.seq(), move, String.format(java.util.Locale.ROOT,
                    "from (%.2f, %.2f) is not where %s is: (%.2f, %.2f)", move.from().x(), move.from().z(),
                    agent.name, here.x(), here.z()));
            return;
        }
        Vec3 to = Vec3.ground(move.to().x(), move.to().z());
        MoveResult check = world.checkMove(here.onGround(), to.onGround(), agent.body.radius());
        if (!check.isFree()) {
            reject(agent, move.seq(), move, check.reason());
            return;
        }
        Walking.Contact contact = walking.contact(agent, here, to);
        Outcome outcome = Outcome.ACCEPTED;
        String reason = null;
        if (contact != null) {
            to = contact.stop();
            outcome = Outcome.BLOCKED;
            reason = "blocked by " + contact.other().name;
        }
        double duration = here.groundDistance(to) / agent.body.maxSpeed();
        agent.motion = duration > 0 ? new Motion(here, to, time, duration) : null;
        sim.send(agent.owner, new ActionResultMessage(move.seq(), agent.name, "Move", outcome, reason, to, duration));
        if (duration > 0) {
            sim.broadcast(new AgentMovedMessage(sim.tick(), agent.name, here, to, time, duration), Audience.VIEWERS);
        }
    }

    private void accept(Agent agent, long seq, ClientMessage message) {
        sim.send(agent.owner, new ActionResultMessage(seq, agent.name, Simulation.typeOf(message), Outcome.ACCEPTED,
                null, null, 0));
    }

    private void reject(Agent agent, long seq, ClientMessage message, String reason) {
        sim.send(agent.owner, new ActionResultMessage(seq, agent.name, Simulation.typeOf(message), Outcome.REJECTED,
                reason, null, 0));
    }

    private void notRunning(Agent agent, long seq, ClientMessage message) {
        reject(agent, seq, message, "the game is not running (" + sim.phase().name().toLowerCase(java.util.Locale.ROOT)
                + ")");
    }

}
