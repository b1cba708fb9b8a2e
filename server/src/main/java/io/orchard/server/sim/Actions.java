package io.orchard.server.sim;

import io.orchard.protocol.MessageTypes;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.AgentRotatedMessage;
import io.orchard.protocol.message.AnimationStartedMessage;
import io.orchard.protocol.message.AnimationStoppedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.JointRotatedMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.StopAnimationMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.MoveResult;
import io.orchard.server.world.World;
import java.util.Map;

/**
 * An agent's actions: every client message about one agent ({@link AgentMessage}) is handled here,
 * once it is known that the sending connection drives that agent. Each is checked against the world
 * and carried out when valid, and answered: most with an {@link ActionResultMessage}, a grasp later
 * with its result (see {@link Grasps}), speech by being relayed. A rejected action changes nothing
 * and no viewer hears of it.
 */
final class Actions {

    private final World world;
    /** The agents in the world, by name. */
    private final Map<String, Agent> agents;
    private final Walking walking;
    private final Grasps grasps;
    private final Registrations registrations;
    private final Outbox outbox;

    Actions(World world, Map<String, Agent> agents, Walking walking, Grasps grasps, Registrations registrations,
            Outbox outbox) {
        this.world = world;
        this.agents = agents;
        this.walking = walking;
        this.grasps = grasps;
        this.registrations = registrations;
        this.outbox = outbox;
    }

    /** Carries out {@code action}, sent with {@code seq} by {@code session}, in a game at {@code phase}. */
    void act(ClientSession session, long seq, AgentMessage action, Phase phase) {
        Agent agent = owned(session, seq, action.agent());
        if (agent == null) {
            return;
        }
        long tick = outbox.tick();
        boolean running = phase == Phase.RUNNING;
        if (action instanceof MoveMessage m) {
            move(agent, m, phase);
        } else if (action instanceof SetRotationMessage m) {
            if (!m.rotation().isAboutUpAxis()) {
                Vec3 axis = m.rotation().axis();
                reject(agent, m.seq(), m, String.format(java.util.Locale.ROOT, "an agent turns only about the up axis"
                        + " (0, 1, 0), axis was (%s, %s, %s)", axis.x(), axis.y(), axis.z()));
            } else if (!running) {
                notRunning(agent, m.seq(), m, phase);
            } else {
                agent.heading = Angles.normalise(m.rotation().headingAngle());
                accept(agent, m.seq(), m);
                outbox.broadcast(new AgentRotatedMessage(tick, agent.name, m.rotation()), Audience.VIEWERS);
            }
        } else if (action instanceof SetJointRotationMessage m) {
            if (!agent.joints.contains(m.joint())) {
                reject(agent, m.seq(), m, "joint " + m.joint() + " not registered");
            } else {
                accept(agent, m.seq(), m);
                outbox.broadcast(new JointRotatedMessage(tick, agent.name, m.joint(), m.rotation()), Audience.VIEWERS);
            }
        } else if (action instanceof StartAnimationMessage m) {
            if (!agent.timeSensors.contains(m.timeSensor())) {
                reject(agent, m.seq(), m, "time sensor " + m.timeSensor() + " not registered");
            } else {
                accept(agent, m.seq(), m);
                outbox.broadcast(new AnimationStartedMessage(tick, agent.name, m.timeSensor(), m.loop()),
                        Audience.VIEWERS);
            }
        } else if (action instanceof StopAnimationMessage m) {
            if (!agent.timeSensors.contains(m.timeSensor())) {
                reject(agent, m.seq(), m, "time sensor " + m.timeSensor() + " not registered");
            } else {
                accept(agent, m.seq(), m);
                outbox.broadcast(new AnimationStoppedMessage(tick, agent.name, m.timeSensor()), Audience.VIEWERS);
            }
        } else if (action instanceof GraspRequestMessage m) {
            grasps.request(agent, m, running);
        } else if (action instanceof PerceptionRequestMessage m) {
            agent.perceptionRequested = true;
            agent.perceptionEvery = m.every();
            agent.nextPerceptionTick = tick + 1 + m.every();
            accept(agent, m.seq(), m);
        } else if (action instanceof RegisterJointMessage m) {
            agent.joints.add(m.joint());
            accept(agent, m.seq(), m);
        } else if (action instanceof RegisterTimeSensorMessage m) {
            agent.timeSensors.add(m.timeSensor());
            accept(agent, m.seq(), m);
        } else if (action instanceof UnregisterMessage m) {
            accept(agent, m.seq(), m);
            registrations.remove(agent, "unregistered");
        } else if (action instanceof SayMessage m) {
            outbox.broadcast(m, Audience.ALL);
        }
    }

    /** The session's agent of that name, or null after answering with the reason it is not. */
    private Agent owned(ClientSession session, long seq, String name) {
        if (session.role() != Role.AGENT) {
            outbox.send(session, new ErrorMessage(seq, ErrorCode.WRONG_ROLE, "a viewer cannot drive agents"));
            return null;
        }
        Agent agent = agents.get(name);
        if (agent == null) {
            outbox.send(session, new ErrorMessage(seq, ErrorCode.UNKNOWN_AGENT, "no agent named '" + name
                    + "' in the world"));
            return null;
        }
        if (agent.owner != session) {
            outbox.send(session, new ErrorMessage(seq, ErrorCode.NOT_YOUR_AGENT,
                    "agent '" + name + "' belongs to another connection"));
            return null;
        }
        return agent;
    }

    private void move(Agent agent, MoveMessage move, Phase phase) {
        if (phase != Phase.RUNNING) {
            notRunning(agent, move.seq(), move, phase);
            return;
        }
        double time = outbox.time();
        Vec3 here = agent.position;
        // Without a from the agent walks from wherever it is now, however late the move arrived.
        if (move.from() != null && here.groundDistance(move.from()) > MoveMessage.FROM_TOLERANCE) {
            reject(agent, move.seq(), move, "from (" + Decimals.twoPlaces(move.from().x()) + ", "
                    + Decimals.twoPlaces(move.from().z()) + ") is not where " + agent.name + " is: ("
                    + Decimals.twoPlaces(here.x()) + ", " + Decimals.twoPlaces(here.z()) + "), it may be at most "
                    + MoveMessage.FROM_TOLERANCE + " units away");
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
        outbox.send(agent.owner, new ActionResultMessage(move.seq(), agent.name, "Move", outcome, reason, to,
                duration));
        if (duration > 0) {
            outbox.broadcast(new AgentMovedMessage(outbox.tick(), agent.name, here, to, time, duration),
                    Audience.VIEWERS);
        }
    }

    private void accept(Agent agent, long seq, ClientMessage message) {
        answer(agent, seq, message, Outcome.ACCEPTED, null);
    }

    private void reject(Agent agent, long seq, ClientMessage message, String reason) {
        answer(agent, seq, message, Outcome.REJECTED, reason);
    }

    private void answer(Agent agent, long seq, ClientMessage message, Outcome outcome, String reason) {
        outbox.send(agent.owner, new ActionResultMessage(seq, agent.name, MessageTypes.nameOf(message.getClass()),
                outcome, reason, null, 0));
    }

    private void notRunning(Agent agent, long seq, ClientMessage message, Phase phase) {
        reject(agent, seq, message, "the game is not running (" + phase.name().toLowerCase(java.util.Locale.ROOT)
                + ")");
    }
}
