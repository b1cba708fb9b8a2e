package io.orchard.server.sim;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Recorder.Audience;
import io.orchard.server.world.World;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.function.BiPredicate;
import java.util.random.RandomGenerator;

/**
 * Agents registering with the simulation and leaving it, as the paper's {@code RegisterMessage} and
 * {@code UnregisterMessage} have it, and coming back: each registered agent gets a resume token, a
 * secret with which its controller gets it back after a dropped connection or, from a checkpoint,
 * after a restart.
 *
 * <p>What decides the game's course is here: where each agent stands at first, drawn from the
 * game's seed and its name alone, and its own seed, which it draws its random numbers from. Neither
 * depends on the order in which agents came: an agent registered before the game starts is placed
 * clear of the world's obstacles only, and at the start ({@link #settle()}) agents are checked in
 * the order of their names, each moving on to its next place if it touches an agent of an earlier
 * name.
 */
final class Registrations {

    /** The most different agent names a game takes: each keeps a score for the whole game. */
    static final int MAX_NAMES = 100_000;

    /** {@link #MAX_NAMES}, smaller in tests. */
    int maxNames = MAX_NAMES;

    private final World world;
    private final SimulationConfig config;
    private final long seed;
    private final Placement placement;
    /** The agents in the world, by name. */
    private final Map<String, Agent> agents;
    private final Scoreboard scores;
    private final Walking walking;
    private final Game game;
    private final Outbox outbox;
    private final List<GameListener> listeners;
    private final SecureRandom secrets = new SecureRandom();
    /** Agents of a restored game, waiting for their controllers: their names are reserved. */
    private final Map<String, Checkpoint.SavedAgent> waiting = new LinkedHashMap<>();
    /** Agents whose connection dropped, kept so that their controllers can get them back; their names reserved. */
    final Departures departed = new Departures();

    Registrations(World world, SimulationConfig config, long seed, Placement placement, Map<String, Agent> agents,
                  Scoreboard scores, Walking walking, Game game, Outbox outbox, List<GameListener> listeners) {
        this.world = world;
        this.config = config;
        this.seed = seed;
        this.placement = placement;
        this.agents = agents;
        this.scores = scores;
        this.walking = walking;
        this.game = game;
        this.outbox = outbox;
        this.listeners = listeners;
    }

    /** Puts a new agent into the world, or gets back one of a restored game or a dropped connection. */
    void register(ClientSession session, RegisterMessage register) {
        long seq = register.seq();
        String name = register.name();
        Checkpoint.SavedAgent reserved = waiting.get(name);
        Checkpoint.SavedAgent left = departed.of(name);
        boolean leftWithToken = left != null && tokenMatches(left.resumeToken(), register.resumeToken());
        String keptForItsController = left != null && !leftWithToken ? departed.whyReserved(name) : null;
        if (session.role() != Role.AGENT) {
            refuse(session, seq, ErrorCode.WRONG_ROLE, "a viewer cannot register agents");
        } else if (game.phase() == Phase.OVER) {
            refuse(session, seq, ErrorCode.GAME_NOT_RUNNING, "the game is over");
        } else if (agents.containsKey(name)) {
            refuse(session, seq, ErrorCode.NAME_IN_USE, "an agent named '" + name + "' is already in the world");
        } else if (reserved != null && !tokenMatches(reserved.resumeToken(), register.resumeToken())) {
            refuse(session, seq, ErrorCode.NAME_IN_USE, "agent '" + name + "' of the saved game is "
                    + "waiting for its controller: register it with its resumeToken");
        } else if (keptForItsController != null) {
            refuse(session, seq, ErrorCode.NAME_IN_USE, keptForItsController);
        } else if (agents.values().stream().filter(a -> a.owner == session).count() >= config.agentsPerSession()) {
            refuse(session, seq, ErrorCode.TOO_MANY_AGENTS, "a connection may drive at most "
                    + config.agentsPerSession() + " agents");
        } else if (reserved != null) {
            if (resume(session, seq, reserved)) {
                waiting.remove(name);
            }
            if (waiting.isEmpty()) {
                game.allBack();
            }
        } else if (leftWithToken) {
            if (resume(session, seq, left)) {
                departed.forget(name);
            }
        } else if (scores.size() >= maxNames && !scores.has(name)) {
            refuse(session, seq, ErrorCode.TOO_MANY_AGENTS, "this game has had " + maxNames
                    + " different agents, the most it takes");
        } else {
            Body body = config.bodyLimits().cap(register.body());
            RandomGenerator draws = placing(name);
            // Before the start, where others stand is left to the start: it depends on who came first.
            Vec3 place = placeFor(name, body.radius(), draws, game.phase() == Phase.WAITING
                    ? (point, radius) -> true : (point, radius) -> walking.clearOfAgents(point, radius, null));
            if (place == null) {
                refuse(session, seq, ErrorCode.TOO_MANY_AGENTS, "no free place left for another agent");
                return;
            }
            double heading = Angles.normalise(draws.nextDouble() * 2 * Math.PI - Math.PI);
            departed.forget(name);
            enter(session, seq, new Agent(name, session, body, register.model(), place, heading, newToken()));
            game.agentEntered(agents.size());
        }
    }

    /**
     * A connection closed: its agents leave, kept so that their controllers can get them back, and
     * their names reserved for them for a while ({@link Departures}).
     */
    void leave(ClientSession session, String reason) {
        List<Agent> owned = agents.values().stream().filter(a -> a.owner == session).toList();
        for (Agent agent : owned) {
            departed.left(agent.saved());
            remove(agent, reason);
        }
    }

    /** Takes an agent out of the world. */
    void remove(Agent agent, String reason) {
        agents.remove(agent.name);
        walking.agentsChanged();
        outbox.broadcast(new AgentRemovedMessage(outbox.tick(), agent.name, reason), Audience.ALL);
        listeners.forEach(l -> l.agentLeft(agent.name, reason));
    }

    /** Reserves the names of a restored game's agents until their controllers register them again. */
    void restore(List<Checkpoint.SavedAgent> saved) {
        for (Checkpoint.SavedAgent agent : saved) {
            waiting.put(agent.name(), agent);
        }
    }

    /** The agents of a restored game that are still waiting for their controllers. */
    List<Checkpoint.SavedAgent> waiting() {
        return new ArrayList<>(waiting.values());
    }

    /**
     * Puts a saved agent back: where it stood if that place is still free, else at a free place.
     * Returns false, having answered why, when there is no free place left.
     */
    private boolean resume(ClientSession session, long seq, Checkpoint.SavedAgent saved) {
        Vec3 place = saved.position();
        double radius = saved.body().radius();
        if (!world.checkPlace(place.onGround(), radius).isFree() || !walking.clearOfAgents(place, radius, null)) {
            place = placeFor(saved.name(), radius, placing(saved.name()),
                    (point, r) -> walking.clearOfAgents(point, r, null));
            if (place == null) {
                refuse(session, seq, ErrorCode.TOO_MANY_AGENTS, "no free place left for another agent");
                return false;
            }
        }
        Agent agent = new Agent(saved.name(), session, saved.body(), saved.model(), place, saved.heading(),
                saved.resumeToken());
        agent.joints.addAll(saved.joints());
        agent.timeSensors.addAll(saved.timeSensors());
        enter(session, seq, agent);
        return true;
    }

    private void enter(ClientSession session, long seq, Agent agent) {
        agents.put(agent.name, agent);
        walking.agentsChanged();
        scores.join(agent.name);
        RegisteredMessage registered = new RegisteredMessage(seq, agent.name, agent.body, agent.position,
                agent.heading, agent.resumeToken, AgentSeed.of(seed, agent.name));
        outbox.send(session, session.protocolVersion() >= 2 ? registered : registered.withoutSeed());
        outbox.broadcast(new AgentAddedMessage(outbox.tick(), agent.state()), Audience.VIEWERS);
        listeners.forEach(l -> l.agentJoined(agent.name));
    }

    private void refuse(ClientSession session, long seq, ErrorCode code, String why) {
        outbox.send(session, new ErrorMessage(seq, code, why));
    }

    /**
     * The draws that place an agent and turn it at first, from the game's seed and the agent's name
     * alone: an agent starts where it started in any other game of the seed with the same agents,
     * whichever joined first.
     */
    private RandomGenerator placing(String name) {
        return new SplittableRandom(seed ^ (name.hashCode() * 0x9E3779B97F4A7C15L) ^ 0x5DEECE66DL);
    }

    /**
     * At the start of the game: each agent, in the order of the names, that touches an agent of an
     * earlier name moves to its next free place (viewers see it jump there; the agent learns it from
     * its first perception). The places then depend on the seed and the names alone.
     */
    void settle() {
        List<Agent> settled = new ArrayList<>();
        BiPredicate<Vec3, Double> clear = (point, radius) -> settled.stream()
                .allMatch(other -> other.position.groundDistance(point) >= radius + other.body.radius());
        for (Agent agent : agents.values()) {
            if (!clear.test(agent.position, agent.body.radius())) {
                Vec3 place = placeFor(agent.name, agent.body.radius(), placing(agent.name), clear);
                if (place != null) {
                    outbox.broadcast(new AgentMovedMessage(outbox.tick(), agent.name, agent.position, place,
                            outbox.time(), 0), Audience.VIEWERS);
                    agent.position = place;
                }
            }
            settled.add(agent);
        }
        walking.agentsChanged();
    }

    /**
     * A free place for a body of this radius, {@code clear} of the agents it must not touch: the
     * placement's, or drawn from the game's seed and the name.
     */
    private Vec3 placeFor(String name, double radius, RandomGenerator draws, BiPredicate<Vec3, Double> clear) {
        Vec3 wanted = placement.placeFor(name, radius);
        if (wanted != null && world.checkPlace(wanted.onGround(), radius).isFree() && clear.test(wanted, radius)) {
            return Vec3.ground(wanted.x(), wanted.z());
        }
        for (int attempt = 0; attempt < 500; attempt++) {
            Vec3 candidate = world.randomFreePoint(draws, radius + 0.1);
            if (candidate != null && clear.test(candidate, radius)) {
                return candidate;
            }
        }
        return null;
    }

    /** A new resume token: 128 random bits, in hex. */
    private String newToken() {
        byte[] bytes = new byte[16];
        secrets.nextBytes(bytes);
        return HexFormat.of().formatHex(bytes);
    }

    /** Compares in time independent of where the tokens differ, so timing does not reveal a token. */
    private static boolean tokenMatches(String expected, String offered) {
        return offered != null && MessageDigest.isEqual(expected.getBytes(StandardCharsets.UTF_8),
                offered.getBytes(StandardCharsets.UTF_8));
    }
}
