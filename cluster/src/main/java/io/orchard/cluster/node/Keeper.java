package io.orchard.cluster.node;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps what parcels hold while Pekko moves them to another node ({@link ParcelEntity}): a parcel
 * whose node leaves gives its state here and stops; started on another node, it takes it back. The
 * tick keeps them ({@link TickSingleton}); a cluster without a tick can run a keeper of its own
 * ({@link #behavior}). One actor's alone.
 */
public final class Keeper {

    private static final Logger log = LoggerFactory.getLogger(Keeper.class);

    private final ActorRefResolver resolver;
    private final AtomicLong takenUp;
    private final Map<String, TickCommand.Keep> kept = new HashMap<>();

    /** A keeper that counts in {@code takenUp} the parcels with agents it gave back. */
    Keeper(ActorRefResolver resolver, AtomicLong takenUp) {
        this.resolver = resolver;
        this.takenUp = takenUp;
    }

    /** A keeper as an actor of its own, counting in {@code takenUp} the parcels with agents it gave back. */
    public static Behavior<TickCommand> behavior(AtomicLong takenUp) {
        return Behaviors.setup(context -> {
            Keeper keeper = new Keeper(ActorRefResolver.get(context.getSystem()), takenUp);
            return Behaviors.receive(TickCommand.class)
                    .onMessage(TickCommand.Keep.class, keep -> {
                        keeper.keep(keep);
                        return Behaviors.same();
                    })
                    .onMessage(TickCommand.Restore.class, restore -> {
                        keeper.restore(restore);
                        return Behaviors.same();
                    })
                    .build();
        });
    }

    /** A parcel whose node leaves: its state is kept, and it is told so, to stop. */
    void keep(TickCommand.Keep keep) {
        kept.put(keep.id(), keep);
        // Said, because a parcel with no agents of its own may start again elsewhere only much later.
        log.info("parcel {} kept while it moves to another node, with {} agents of its own", keep.id(),
                keep.state().own().size());
        resolver.<ParcelCommand>resolveActorRef(keep.parcel()).tell(new ParcelCommand.Kept());
    }

    /** A parcel started: it gets what was kept of it, or nothing. */
    void restore(TickCommand.Restore restore) {
        TickCommand.Keep state = kept.remove(restore.id());
        if (state != null && state.state().hasAgents()) {
            takenUp.incrementAndGet();
        }
        resolver.<ParcelCommand>resolveActorRef(restore.parcel()).tell(state == null
                ? new ParcelCommand.Restored(null, 0, null)
                : new ParcelCommand.Restored(state.state(), state.lastStep(), state.lastReply()));
    }

    /** Forgets everything kept: the world rolls back, and the parcels start anew. */
    void forget() {
        kept.clear();
    }
}
