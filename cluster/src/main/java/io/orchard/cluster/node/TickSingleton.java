package io.orchard.cluster.node;

import io.orchard.cluster.game.SplitGame;
import io.orchard.protocol.MessageCodec;
import io.orchard.server.sim.Recorder;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import java.util.function.Supplier;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.PostStop;
import org.apache.pekko.actor.typed.javadsl.Behaviors;

/**
 * The tick of the cluster's one game, a Pekko cluster singleton: it runs on one node at a time (the
 * oldest), where it holds the game ({@link SplitGame} over the sharded parcels) and the thread that
 * drives its clock ({@link SplitLoop}); every gateway tells it what its clients do, and it sends
 * each client's lines back to that client's gateway.
 */
public final class TickSingleton {

    private static final MessageCodec CODEC = new MessageCodec();

    private TickSingleton() {}

    /**
     * The singleton's behaviour: when it starts on a node, {@code recorders} opens the recording
     * there and {@code games} makes the game recorded to it.
     */
    public static Behavior<TickCommand> create(Function<Recorder, SplitGame> games, Supplier<Recorder> recorders) {
        return Behaviors.setup(context -> {
            ActorRefResolver resolver = ActorRefResolver.get(context.getSystem());
            Recorder recorder = recorders.get();
            SplitGame game = games.apply(recorder);
            Set<ActorRef<GatewayCommand>> gateways = ConcurrentHashMap.newKeySet();
            SplitLoop loop = new SplitLoop(game, game.config(), (phase, tick) -> {
                        GatewayCommand.Clock clock = new GatewayCommand.Clock(tick, phase.name());
                        gateways.forEach(gateway -> gateway.tell(clock));
                    });
            Thread thread = new Thread(loop, "orchard-split-tick");
            thread.setDaemon(true);
            thread.start();
            Map<Long, RemoteSession> sessions = new HashMap<>();
            return Behaviors.receive(TickCommand.class)
                    .onMessage(TickCommand.Connected.class, connected -> {
                        ActorRef<GatewayCommand> gateway = resolver.resolveActorRef(connected.gateway());
                        gateways.add(gateway);
                        RemoteSession session = new RemoteSession(connected.session(), connected.role(),
                                connected.protocolVersion(), gateway);
                        sessions.put(connected.session(), session);
                        game.connected(session);
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Received.class, received -> {
                        RemoteSession session = sessions.get(received.session());
                        if (session != null) {
                            game.received(session, CODEC.decodeClient(received.line()));
                        }
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Disconnected.class, gone -> {
                        RemoteSession session = sessions.remove(gone.session());
                        if (session != null) {
                            session.gone();
                            game.disconnected(session, "connection closed");
                        }
                        return Behaviors.same();
                    })
                    .onSignal(PostStop.class, stop -> {
                        loop.stop();
                        thread.join(5_000);
                        recorder.close();
                        return Behaviors.same();
                    })
                    .build();
        });
    }
}
