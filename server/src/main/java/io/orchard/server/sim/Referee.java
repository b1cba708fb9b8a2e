package io.orchard.server.sim;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The game of a world simulated in parts ({@link PartialSimulation}), without the world's work: who
 * is in the game and whose they are, registrations and resume tokens, the names kept for dropped
 * agents, the scores, the phase with its pauses and its end, the lockstep turns, what a client that
 * connects late is told, and the whole game saved. A program that runs the parts on several threads
 * or machines keeps the referee on one (Orchard's cluster); a game that started in a
 * {@link Simulation} goes on with the referee {@link Simulation#referee} hands over, with the same
 * rules, the single server's own.
 *
 * <p>The referee knows where the agents stand as its caller last told it ({@link #refresh}): the
 * parts move them. What it says goes to the recorder it was handed over with, a message to one
 * client also to that client's session; broadcasts are the caller's to deliver. Not thread-safe: one
 * thread at a time, as a {@link Simulation}.
 */
public final class Referee {

    private final World world;
    private final SimulationConfig config;
    private final long seed;
    private final Map<String, Agent> agents;
    private final Registrations registrations;
    private final Game game;
    private final Scoreboard scores;
    private final Turns turns;
    private final Outbox outbox;
    private final Walking walking;
    private final List<GameListener> listeners;
    private final String oneGameOnly;

    Referee(World world, SimulationConfig config, long seed, Map<String, Agent> agents, Registrations registrations,
            Game game, Scoreboard scores, Turns turns, Outbox outbox, Walking walking, List<GameListener> listeners,
            String oneGameOnly) {
        this.world = world;
        this.config = config;
        this.seed = seed;
        this.agents = agents;
        this.registrations = registrations;
        this.game = game;
        this.scores = scores;
        this.turns = turns;
        this.outbox = outbox;
        this.walking = walking;
        this.listeners = listeners;
        this.oneGameOnly = oneGameOnly;
    }

    // ---- the clock and the phase ----------------------------------------------------------------

    /** Sets the clock that stamps what is said from now on. */
    public void at(long tick, double time) {
        outbox.at(tick, time);
    }

    /** The tick that runs now (the next to begin, between ticks). */
    public long tick() {
        return outbox.tick();
    }

    /** Simulated seconds since the game started. */
    public double time() {
        return outbox.time();
    }

    /** The current phase. */
    public Phase phase() {
        return game.phase();
    }

    /**
     * A client's start, pause or resume, answered with whether it was done; a restart is refused, as
     * by a server that plays one game only.
     */
    public void control(ClientSession session, GameControlMessage control) {
        if (control.command() == GameCommand.RESTART) {
            outbox.send(session, new ActionResultMessage(control.seq(), null, "GameControl", Outcome.REJECTED,
                    oneGameOnly, null, 0));
        } else {
            game.control(session, control);
        }
    }

    /** Pauses a running game or continues a paused one; returns the phase after. */
    public Phase togglePause() {
        return game.togglePause();
    }

    /** Ends the game when the fruit is gone or the time is up; true when it is over. */
    public boolean checkOver() {
        game.checkOver();
        return game.phase() == Phase.OVER;
    }

    /** Ends the game now with this reason; no effect once over. */
    public void end(String reason) {
        game.end(reason);
    }

    // ---- the agents -------------------------------------------------------------------------------

    /** The agents as they stand now, as the parts that own them said: where, facing, walking, registered. */
    public void refresh(Collection<AgentHandover> now) {
        for (AgentHandover state : now) {
            Agent agent = agents.get(state.name());
            if (agent != null) {
                agent.position = state.position();
                agent.heading = state.heading();
                agent.motion = state.walk() == null ? null : state.walk().motion();
                agent.joints.clear();
                agent.joints.addAll(state.joints());
                agent.timeSensors.clear();
                agent.timeSensors.addAll(state.timeSensors());
                agent.perceptionRequested = state.perceptionRequested();
                agent.perceptionEvery = state.perceptionEvery();
                agent.nextPerceptionTick = state.nextPerceptionTick();
            }
        }
        walking.agentsChanged();
    }

    /** Every agent in the game, by name, with the session that drives it. */
    public List<PartialSimulation.Driven> agents() {
        List<PartialSimulation.Driven> all = new ArrayList<>();
        for (Agent agent : agents.values()) {
            all.add(driven(agent));
        }
        return all;
    }

    /** Names of the agents of a restored game that are still waiting for their controllers. */
    public List<String> waitingAgents() {
        return registrations.waiting().stream().map(Checkpoint.SavedAgent::name).toList();
    }

    private PartialSimulation.Driven driven(Agent agent) {
        return new PartialSimulation.Driven(agent.handover(), agent.owner, outbox.label(agent.owner));
    }

    /**
     * A client's {@code Register}, recorded and answered as one server answers it: a new agent is
     * placed clear of the world's obstacles and of the agents where they stand now, a returning one
     * (with its resume token) where it stood if that place is free.
     *
     * @return the agent that entered the game, or null when none did
     */
    public PartialSimulation.Driven register(ClientSession session, RegisterMessage register) {
        outbox.accepted(session, register);
        Agent before = agents.get(register.name());
        registrations.register(session, register);
        Agent after = agents.get(register.name());
        return after != null && after != before ? driven(after) : null;
    }

    /**
     * A client's connection closed: its agents leave the game, kept (as they were last
     * {@linkplain #refresh told}) so that their controllers can get them back, their names reserved
     * for a while; viewers hear it.
     *
     * @return the names of the agents that left
     */
    public List<String> leave(ClientSession session, String reason) {
        turns.forget(session.id());
        List<String> left = agents.values().stream().filter(a -> a.owner == session).map(a -> a.name).toList();
        registrations.leave(session, reason);
        outbox.forgetLabel(session);
        return left;
    }

    /** An agent unregistered (its part said so to the viewers): it is out of the game, its name free. */
    public void unregistered(String name) {
        if (agents.remove(name) != null) {
            walking.agentsChanged();
            listeners.forEach(l -> l.agentLeft(name, "unregistered"));
        }
    }

    /** A fruit was collected in a part: the agent scores, and the fruit is gone from the referee's world. */
    public void collected(String agent, String fruit, FruitKind kind, double time) {
        world.removeFruit(fruit);
        scores.collect(agent, kind);
        listeners.forEach(l -> l.fruitEaten(agent, fruit, kind, time));
    }

    /** Every agent's score, best first. */
    public List<Score> ranking() {
        return scores.ranking();
    }

    // ---- what is said -----------------------------------------------------------------------------

    /** How the record names a client. */
    public String label(ClientSession session) {
        return outbox.label(session);
    }

    /** Records a client's message that is about to be applied. */
    public void accepted(ClientSession session, ClientMessage message) {
        outbox.accepted(session, message);
    }

    /** Sends a message to one client, recorded. */
    public void send(ClientSession session, ServerMessage message) {
        outbox.send(session, message);
    }

    /** Records a message to an audience; its delivery is the caller's. */
    public void broadcast(ServerMessage message, Audience audience) {
        outbox.broadcast(message, audience);
    }

    /**
     * What a client that connected now is told to catch up with the game, which the record holds
     * already: a viewer the world as it is now and every agent in it; every client of a game under way
     * its {@code GameStarted}, the seed to viewers only.
     */
    public List<ServerMessage> catchUp(ClientSession session) {
        List<ServerMessage> said = new ArrayList<>();
        boolean viewer = session.role() == Role.VIEWER;
        if (viewer) {
            said.add(world.snapshot(outbox.tick(), outbox.time(), scores.ranking()));
            for (Agent agent : agents.values()) {
                said.add(new AgentAddedMessage(outbox.tick(), agent.state()));
            }
        }
        if (game.phase() == Phase.RUNNING || game.phase() == Phase.PAUSED) {
            GameStartedMessage started = new GameStartedMessage(0, seed, game.fruitAtStart(), config.timeLimit());
            said.add(viewer ? started : started.withoutSeed());
        }
        return said;
    }

    // ---- lockstep turns ---------------------------------------------------------------------------

    /** Lockstep: a tick begins, whose turns are those of the agents' clients now. */
    public void tickBegins() {
        turns.began(agentSessions());
    }

    /** Lockstep: the clients this tick waits for, those of agents but the late ones. */
    public List<Long> turnsToWaitFor() {
        return turns.waitFor();
    }

    /**
     * Lockstep: the tick {@code tick} ended, and these clients had ended their turns in it; every
     * turn the game went on without is recorded, client by client in the order of their agents'
     * names, and returned in that order.
     */
    public List<MissedTurn> turnsEnded(long tick, Set<Long> ended) {
        List<MissedTurn> all = new ArrayList<>();
        turns.ended(ended, agentSessions()).forEach((id, kind) -> {
            ClientSession client = null;
            List<String> names = new ArrayList<>();
            for (Agent agent : agents.values()) {
                if (agent.owner.id() == id) {
                    client = agent.owner;
                    names.add(agent.name);
                }
            }
            if (client != null) {
                MissedTurn missed = new MissedTurn(tick, names, kind);
                outbox.missed(client, missed);
                listeners.forEach(l -> l.turnMissed(missed));
                all.add(missed);
            }
        });
        return all;
    }

    private List<Long> agentSessions() {
        return agents.values().stream().map(a -> a.owner.id()).distinct().toList();
    }

    // ---- saving -----------------------------------------------------------------------------------

    /** The whole game as it is now, the agents as last {@linkplain #refresh told}. */
    public Checkpoint checkpoint() {
        List<Checkpoint.SavedAgent> saved = registrations.waiting();
        agents.values().forEach(agent -> saved.add(agent.saved()));
        return Checkpoint.of(seed, config, game.phase(), outbox.tick(), outbox.time(), game.fruitAtStart(), world,
                saved, scores.ranking());
    }
}
