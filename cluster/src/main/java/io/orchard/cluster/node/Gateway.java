package io.orchard.cluster.node;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GamePhase;
import io.orchard.protocol.value.Role;
import io.orchard.server.Version;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.Inbox;
import io.orchard.server.sim.SimulationConfig;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.actor.typed.receptionist.ServiceKey;

/**
 * A node's door for agents and viewers: the server's own network front end
 * ({@code io.orchard.server.net.NetServer}) hands it what its clients do, and it passes that to the
 * tick, wherever in the cluster the tick runs; the tick's lines for its clients come back to its
 * actor ({@link #behavior}) and go out on their connections. A client cannot tell it from a server.
 * Clients are numbered across the cluster: the node's number in the upper half of a session's
 * number, the connection's in the lower.
 */
public final class Gateway implements Inbox {

    /** The key under which every node's gateway actor is found (Pekko's receptionist). */
    public static final ServiceKey<GatewayCommand> KEY = ServiceKey.create(GatewayCommand.class, "orchard-gateways");

    private static final MessageCodec CODEC = new MessageCodec();

    private final long node;
    private volatile ActorRef<TickCommand> tick;
    private final Bounds bounds;
    private final SimulationConfig config;
    private final Map<Long, ClientSession> sessions = new ConcurrentHashMap<>();
    private volatile String self;
    private volatile long clockTick;
    private volatile GamePhase phase = GamePhase.WAITING;
    /** The epoch of the tick last heard; -1 before any. */
    private volatile long epoch = -1;
    /** Ticks of the lockstep game heard so far, every epoch together: written by the gateway's actor alone. */
    private volatile long lockstepTicks;

    /**
     * The gateway of node number {@code node} (a number no other node of the cluster has), for a
     * world of {@code bounds} and a game of {@code config}.
     */
    public Gateway(int node, Bounds bounds, SimulationConfig config) {
        this.node = (long) node << 32;
        this.bounds = bounds;
        this.config = config;
    }

    /** Its actor, as the tick addresses it, and the tick it tells what its clients do: set before clients come. */
    public void attach(String actor, ActorRef<TickCommand> tick) {
        this.self = actor;
        this.tick = tick;
    }

    /** The actor that writes the tick's lines to this gateway's clients: all writes happen on it. */
    public static Behavior<GatewayCommand> behavior(Gateway gateway) {
        return Behaviors.receive(GatewayCommand.class)
                .onMessage(GatewayCommand.Deliver.class, deliver -> {
                    ClientSession session = gateway.sessions.get(deliver.session());
                    if (session != null) {
                        deliver.lines().forEach(line -> session.send(CODEC.decodeServer(line)));
                        session.flush();
                    }
                    return Behaviors.same();
                })
                .onMessage(GatewayCommand.Close.class, close -> {
                    ClientSession session = gateway.sessions.get(close.session());
                    if (session != null) {
                        session.close((ErrorMessage) CODEC.decodeServer(close.line()));
                    }
                    return Behaviors.same();
                })
                .onMessage(GatewayCommand.Clock.class, clock -> {
                    if (clock.epoch() >= gateway.epoch) {
                        if (clock.epoch() == gateway.epoch && clock.tick() > gateway.clockTick
                                && gateway.config.clock() == ClockMode.LOCKSTEP) {
                            gateway.lockstepTicks = gateway.lockstepTicks + clock.tick() - gateway.clockTick;
                        }
                        gateway.epoch = clock.epoch();
                        gateway.clockTick = clock.tick();
                        gateway.phase = GamePhase.valueOf(clock.phase());
                    }
                    return Behaviors.same();
                })
                .onMessage(GatewayCommand.Rollback.class, rollback -> {
                    gateway.epoch = Math.max(gateway.epoch, rollback.epoch());
                    ErrorMessage last = (ErrorMessage) CODEC.decodeServer(rollback.line());
                    for (ClientSession session : List.copyOf(gateway.sessions.values())) {
                        session.close(last);
                    }
                    return Behaviors.same();
                })
                .build();
    }

    /** The epoch of the tick last heard, -1 before any: whether a tick ran before on this cluster. */
    public long epoch() {
        return epoch;
    }

    /** Whether the tick last heard had a game under way (started, and not over). */
    public boolean heardAGameUnderWay() {
        return epoch >= 0 && (phase == GamePhase.RUNNING || phase == GamePhase.PAUSED);
    }

    /** Whether the tick last heard had played its game to the end. */
    public boolean heardTheGameOver() {
        return epoch >= 0 && phase == GamePhase.OVER;
    }

    /** The tick the game is at, as the tick last said. */
    public long tick() {
        return clockTick;
    }

    /** The game's phase, as the tick last said. */
    public GamePhase phase() {
        return phase;
    }

    /** How many clients are connected to this gateway. */
    public int clients() {
        return sessions.size();
    }

    private long number(ClientSession session) {
        return node | session.id();
    }

    @Override
    public void connected(ClientSession session) {
        sessions.put(number(session), session);
        tick.tell(new TickCommand.Connected(number(session), session.role(), session.protocolVersion(), self));
    }

    @Override
    public void received(ClientSession session, ClientMessage message) {
        tick.tell(new TickCommand.Received(number(session), CODEC.encode(message)));
    }

    @Override
    public void disconnected(ClientSession session, String reason) {
        sessions.remove(number(session));
        tick.tell(new TickCommand.Disconnected(number(session), reason));
    }

    /**
     * The ticks of the lockstep game played so far, as the tick told this node: a client may send
     * more lines the more ticks pass, as to one server.
     */
    @Override
    public long lockstepTicks() {
        return lockstepTicks;
    }

    @Override
    public WelcomeMessage welcome(long seq, Role role, int protocolVersion) {
        return new WelcomeMessage(seq, protocolVersion, Version.current(), role, bounds, config.tickRate(),
                config.clock(), clockTick, config.timeLimit(), phase).forVersion(protocolVersion);
    }
}
