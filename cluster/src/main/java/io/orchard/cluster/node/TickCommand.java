package io.orchard.cluster.node;

import io.orchard.protocol.value.Role;

/** What a gateway tells the tick ({@link TickSingleton}): its clients coming, speaking and going. */
public sealed interface TickCommand extends ClusterMessage {

    /**
     * A client finished its handshake at the gateway {@code gateway} (an actor reference in Pekko's
     * serialization format).
     */
    record Connected(long session, Role role, int protocolVersion, String gateway) implements TickCommand {}

    /** A client sent this line of the protocol. */
    record Received(long session, String line) implements TickCommand {}

    /** A client's connection closed. */
    record Disconnected(long session) implements TickCommand {}
}
