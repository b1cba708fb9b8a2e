package io.orchard.cluster.node;

import io.orchard.protocol.MessageCodec;
import io.orchard.server.sim.Phase;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.PostStop;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.actor.typed.receptionist.Receptionist;
import org.apache.pekko.cluster.ClusterEvent;
import org.apache.pekko.cluster.MemberStatus;
import org.apache.pekko.cluster.typed.Cluster;
import org.apache.pekko.cluster.typed.Subscribe;

/**
 * The tick of the cluster's one game, a Pekko cluster singleton: it runs on one node at a time (the
 * oldest), where it holds the game ({@link TickRunner}); every gateway tells it what its clients do,
 * and it sends each client's lines back to that client's gateway. It keeps the state of the parcels
 * whose nodes leave until they start elsewhere ({@link ParcelEntity}), and rolls the world back to
 * its checkpoint when a node is lost.
 */
public final class TickSingleton {

    private static final MessageCodec CODEC = new MessageCodec();

    /**
     * What the tick of a node needs.
     *
     * @param making          how it makes its game
     * @param parcels         the parcels, reached from this node
     * @param local           this node's gateway: whether a tick ran a game before on this cluster
     * @param checkpoint      the cluster-wide checkpoint file, or null
     * @param checkpointEvery how often to save the game besides when fruit is taken, or null
     * @param resume          a saved game to go on with, or null
     * @param takenUp         counts the parcels with agents whose state it kept while they moved
     */
    public record Setup(TickGames making, ShardedParcels parcels, Gateway local, Path checkpoint,
                 Duration checkpointEvery, Path resume, AtomicLong takenUp) {}

    private TickSingleton() {}

    /** The singleton's behaviour, on whichever node it runs. */
    public static Behavior<TickCommand> create(Setup setup) {
        return Behaviors.setup(context -> {
            ActorRefResolver resolver = ActorRefResolver.get(context.getSystem());
            Set<ActorRef<GatewayCommand>> gateways = ConcurrentHashMap.newKeySet();
            GatewayCommand[] lastRollback = {null};
            TickRunner runner = new TickRunner(setup.making(), setup.parcels(), setup.checkpoint(),
                    setup.checkpointEvery(), command -> {
                        if (command instanceof GatewayCommand.Rollback) {
                            lastRollback[0] = command;
                        }
                        gateways.forEach(gateway -> gateway.tell(command));
                    });
            context.getSystem().receptionist().tell(Receptionist.subscribe(Gateway.KEY,
                    context.messageAdapter(Receptionist.Listing.class, TickCommand.Gateways::new)));
            Cluster.get(context.getSystem()).subscriptions().tell(Subscribe.create(
                    context.messageAdapter(ClusterEvent.MemberRemoved.class, TickCommand.MemberGone::new),
                    ClusterEvent.MemberRemoved.class));
            runner.start(setup.local().epoch(), setup.local().heardAGameUnderWay(), setup.local().heardTheGameOver(),
                    setup.resume());
            Map<Long, RemoteSession> sessions = new HashMap<>();
            Keeper keeper = new Keeper(resolver, setup.takenUp());
            return Behaviors.receive(TickCommand.class)
                    .onMessage(TickCommand.Connected.class, connected -> {
                        ActorRef<GatewayCommand> gateway = resolver.resolveActorRef(connected.gateway());
                        RemoteSession session = new RemoteSession(connected.session(), connected.role(),
                                connected.protocolVersion(), gateway);
                        sessions.put(connected.session(), session);
                        runner.current().connected(session);
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Received.class, received -> {
                        RemoteSession session = sessions.get(received.session());
                        if (session != null) {
                            runner.current().received(session, CODEC.decodeClient(received.line()));
                        }
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Disconnected.class, gone -> {
                        RemoteSession session = sessions.remove(gone.session());
                        if (session != null) {
                            session.gone();
                            runner.current().disconnected(session, gone.reason());
                        }
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Control.class, control -> {
                        control(runner, control);
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Keep.class, keep -> {
                        keeper.keep(keep);
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Restore.class, restore -> {
                        keeper.restore(restore);
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.MemberGone.class, gone -> {
                        if (gone.removed().previousStatus() == MemberStatus.down()) {
                            keeper.forget();
                            runner.nodeLost("the node " + gone.removed().member().address().hostPort()
                                    + " was lost");
                        }
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Gateways.class, listed -> {
                        Set<ActorRef<GatewayCommand>> now = listed.listing().getServiceInstances(Gateway.KEY);
                        for (ActorRef<GatewayCommand> gateway : now) {
                            if (gateways.add(gateway) && lastRollback[0] != null) {
                                gateway.tell(lastRollback[0]);
                            }
                        }
                        gateways.retainAll(now);
                        return Behaviors.same();
                    })
                    .onSignal(PostStop.class, stop -> {
                        runner.stop();
                        return Behaviors.same();
                    })
                    .build();
        });
    }

    private static void control(TickRunner runner, TickCommand.Control control) {
        if (control.command() == TickCommand.Command.CHECKPOINT) {
            runner.checkpointNow();
            return;
        }
        io.orchard.cluster.game.SplitGame game = runner.current();
        game.execute(() -> {
            switch (control.command()) {
                case START -> game.start();
                case PAUSE -> {
                    if (game.phase() == Phase.RUNNING) {
                        game.togglePause();
                    }
                }
                case RESUME -> {
                    if (game.phase() == Phase.PAUSED) {
                        game.togglePause();
                    }
                }
                case END -> game.end(control.reason());
                default -> { }
            }
        });
    }
}
