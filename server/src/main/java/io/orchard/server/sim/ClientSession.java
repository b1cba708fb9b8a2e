package io.orchard.server.sim;

import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;

/**
 * One connected client as the simulation sees it: something to send messages to. The network layer
 * implements it; the simulation never sees a socket, so tests drive it with plain objects.
 *
 * <p>Sends never block the caller: messages queue up and go out when {@link #flush()} is called (the
 * simulation flushes every session at the end of a tick). A session that cannot keep up is cut off
 * by its implementation.
 */
public interface ClientSession {

    /** A number unique to this connection, assigned in the order clients connected. */
    long id();

    /** What the client said it is in its hello. */
    Role role();

    /** The protocol version the client named in its hello: what it may be sent. */
    default int protocolVersion() {
        return ProtocolVersion.CURRENT;
    }

    /** Queues one message for this client. */
    void send(ServerMessage message);

    /**
     * Queues what its agent perceived in a tick: as its three messages of the ordinary form unless
     * the session writes it in a form of its own ({@link Percept}).
     */
    default void send(Percept percept) {
        percept.messages().forEach(this::send);
    }

    /** Queues a message already encoded once for many clients. */
    void send(EncodedLine line);

    /** Sends what is queued. */
    void flush();

    /** Sends a last error and closes the connection. */
    void close(ErrorMessage last);

    /** Whether the connection is still open. */
    boolean isOpen();
}
