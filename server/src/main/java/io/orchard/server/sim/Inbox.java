package io.orchard.server.sim;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.WelcomeMessage;

/**
 * Where the network layer hands what clients do. Every method may be called from any thread; the
 * simulation queues the calls and acts on them on its own thread, in the order they arrived.
 */
public interface Inbox {

    /** A client finished its handshake; for a viewer, the snapshot follows. */
    void connected(ClientSession session);

    /** A client sent a valid message. */
    void received(ClientSession session, ClientMessage message);

    /** A client's connection closed; its agents leave the world. */
    void disconnected(ClientSession session, String reason);

    /**
     * The welcome for a new client with this hello's seq, role and protocol version (which the
     * welcome repeats), describing the world as it is now.
     */
    WelcomeMessage welcome(long seq, io.orchard.protocol.value.Role role, int protocolVersion);

    /**
     * How many ticks lockstep games have played on this server so far, every game together (0 on a
     * realtime server): a client may send more lines the more ticks pass.
     */
    default long lockstepTicks() {
        return 0;
    }
}
