package io.orchard.cluster.node;

import io.orchard.cluster.parcel.Parcel;
import io.orchard.protocol.value.Role;
import org.apache.pekko.actor.typed.receptionist.Receptionist;
import org.apache.pekko.cluster.ClusterEvent;

/**
 * What the tick ({@link TickSingleton}) is told: by gateways, their clients coming, speaking and
 * going; by a node's operator, what to do with the game.
 */
public sealed interface TickCommand extends ClusterMessage {

    /**
     * A client finished its handshake at the gateway {@code gateway} (an actor reference in Pekko's
     * serialization format).
     */
    record Connected(long session, Role role, int protocolVersion, String gateway) implements TickCommand {}

    /** A client sent this line of the protocol. */
    record Received(long session, String line) implements TickCommand {}

    /** A client's connection closed, for this reason. */
    record Disconnected(long session, String reason) implements TickCommand {}

    /** What a node's operator asks of the game (its console, or the program that embeds it). */
    enum Command {
        /** Start the game now, without waiting for more agents. */
        START,
        /** Pause the game if it runs. */
        PAUSE,
        /** Continue the game if it is paused. */
        RESUME,
        /** End the game now. */
        END,
        /** Save the game to the cluster-wide checkpoint file at the end of the tick. */
        CHECKPOINT
    }

    /** The operator's command, with the reason for an end. */
    record Control(Command command, String reason) implements TickCommand {}

    /**
     * A parcel whose node leaves hands its state to the tick, as the parcels' keeper, and stops once
     * told {@link ParcelCommand.Kept} at {@code parcel} (an actor reference in Pekko's format), with
     * its last step's number and answer, so that the step asked again is not done twice.
     */
    record Keep(String id, Parcel.State state, long lastStep, ParcelReply lastReply, String parcel)
            implements TickCommand {}

    /** A parcel started on a node asks the keeper for its state: {@link ParcelCommand.Restored}. */
    record Restore(String id, String parcel) implements TickCommand {}

    /** A member left the cluster or was lost, as the tick's node hears it; never sent between nodes. */
    record MemberGone(ClusterEvent.MemberRemoved removed) implements TickCommand {}

    /** The gateways the receptionist knows, as the tick's node hears it; never sent between nodes. */
    record Gateways(Receptionist.Listing listing) implements TickCommand {}
}
