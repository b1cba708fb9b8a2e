package io.orchard.cluster.order;

import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;

/**
 * A client as a part of the world sees it: what the part sends it is not sent at once but goes with
 * the line the part recorded for it, to be delivered in the single server's order after the merge,
 * wherever the client is connected. A part never closes a client.
 */
public final class ProxySession implements ClientSession {

    private final SessionRef client;
    private final KeyedLines lines;

    /** The client {@code client}, seen by the part that records to {@code lines}. */
    public ProxySession(SessionRef client, KeyedLines lines) {
        this.client = client;
        this.lines = lines;
    }

    @Override
    public long id() {
        return client.id();
    }

    @Override
    public Role role() {
        return client.role();
    }

    @Override
    public int protocolVersion() {
        return client.protocolVersion();
    }

    @Override
    public void send(ServerMessage message) {
        lines.delivered(client, message);
    }

    @Override
    public void send(EncodedLine line) {
        lines.delivered(client, line.message());
    }

    @Override
    public void flush() {}

    @Override
    public void close(ErrorMessage last) {}

    @Override
    public boolean isOpen() {
        return true;
    }
}
