package io.orchard.cluster.order;

import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;

/**
 * A client as the parcels know it, wherever its connection is: the connection's number (unique in
 * the game), what it said it is and the protocol version it speaks. A value, sent between nodes.
 *
 * @param id              the connection's number
 * @param role            agent or viewer
 * @param protocolVersion the protocol version it speaks
 */
public record SessionRef(long id, Role role, int protocolVersion) {

    /** The reference of a connected client. */
    public static SessionRef of(ClientSession session) {
        return new SessionRef(session.id(), session.role(), session.protocolVersion());
    }
}
