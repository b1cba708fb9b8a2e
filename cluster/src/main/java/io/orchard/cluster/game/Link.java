package io.orchard.cluster.game;

import io.orchard.cluster.order.KeyedLines;
import io.orchard.cluster.order.ProxySession;
import io.orchard.cluster.order.SessionRef;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;

/**
 * A client of a split game as the game's lobby and then its referee know it: one object for the
 * connection's whole life, since they tell a client's agents by the session that drives them. Before
 * the start what it is sent goes to the connection at once, as the lobby (a plain simulation) has it;
 * from the start it waits in the game's keyed lines ({@link ProxySession}), to be delivered in the
 * single server's order once the parts' lines are merged.
 */
final class Link implements ClientSession {

    private final ClientSession connection;
    private ProxySession keyed;

    Link(ClientSession connection) {
        this.connection = connection;
    }

    /** From now on what the client is sent waits in {@code lines}. */
    void keyedInto(KeyedLines lines) {
        keyed = new ProxySession(ref(), lines);
    }

    /** The connection. */
    ClientSession connection() {
        return connection;
    }

    /** The client as the parcels know it. */
    SessionRef ref() {
        return SessionRef.of(connection);
    }

    @Override
    public long id() {
        return connection.id();
    }

    @Override
    public Role role() {
        return connection.role();
    }

    @Override
    public int protocolVersion() {
        return connection.protocolVersion();
    }

    @Override
    public void send(ServerMessage message) {
        if (keyed == null) {
            connection.send(message);
        } else {
            keyed.send(message);
        }
    }

    @Override
    public void send(EncodedLine line) {
        if (keyed != null) {
            throw new IllegalStateException("a split game delivers its broadcasts by their keys, not to " + id());
        }
        connection.send(line);
    }

    @Override
    public void flush() {
        if (keyed == null) {
            connection.flush();
        }
    }

    @Override
    public void close(ErrorMessage last) {
        connection.close(last);
    }

    @Override
    public boolean isOpen() {
        return connection.isOpen();
    }
}
