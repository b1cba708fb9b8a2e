package io.orchard.server.sim;

import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import java.util.ArrayList;
import java.util.List;

/** A client session that keeps what it is sent, for stepping the simulation without sockets. */
final class FakeSession implements ClientSession {

    private final long id;
    private final Role role;
    final List<ServerMessage> received = new ArrayList<>();
    /** How many of {@link #received} were flushed, that is sent on their way. */
    int flushed;
    boolean open = true;
    int version = ProtocolVersion.CURRENT;

    FakeSession(long id, Role role) {
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
        return version;
    }

    @Override
    public void send(ServerMessage message) {
        received.add(message);
    }

    @Override
    public void send(EncodedLine line) {
        received.add(line.message());
    }

    @Override
    public void flush() {
        flushed = received.size();
    }

    @Override
    public void close(ErrorMessage last) {
        received.add(last);
        open = false;
    }

    @Override
    public boolean isOpen() {
        return open;
    }

    <T extends ServerMessage> List<T> all(Class<T> type) {
        return received.stream().filter(type::isInstance).map(type::cast).toList();
    }

    <T extends ServerMessage> T last(Class<T> type) {
        List<T> all = all(type);
        if (all.isEmpty()) {
            throw new AssertionError("no " + type.getSimpleName() + " among " + received);
        }
        return all.get(all.size() - 1);
    }
}
