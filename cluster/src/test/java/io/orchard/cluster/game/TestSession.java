package io.orchard.cluster.game;

import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import java.util.ArrayList;
import java.util.List;

/** A client session that keeps what it is sent until its client reads it, for games without sockets. */
final class TestSession implements ClientSession {

    private final long id;
    private final Role role;
    private final List<ServerMessage> unread = new ArrayList<>();
    private final List<ServerMessage> all = new ArrayList<>();

    TestSession(long id, Role role) {
        this.id = id;
        this.role = role;
    }

    @Override
    public long id() {
        return id;
    }

    @Override
    public Role role() {
        return role;
    }

    @Override
    public int protocolVersion() {
        return ProtocolVersion.CURRENT;
    }

    @Override
    public synchronized void send(ServerMessage message) {
        unread.add(message);
        all.add(message);
    }

    @Override
    public void send(EncodedLine line) {
        send(line.message());
    }

    @Override
    public void flush() {}

    @Override
    public void close(ErrorMessage last) {
        send(last);
    }

    @Override
    public boolean isOpen() {
        return true;
    }

    /** Everything it was sent, in order. */
    synchronized List<ServerMessage> all() {
        return List.copyOf(all);
    }

    /** What came since the last read. */
    synchronized List<ServerMessage> read() {
        List<ServerMessage> read = new ArrayList<>(unread);
        unread.clear();
        return read;
    }
}
