package io.orchard.server.bench;

import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Percept;

/**
 * A session that counts what it is sent and drops it, so a benchmark measures the simulation alone;
 * it keeps only where its agent was last perceived, for a benchmark that moves its agents on.
 */
final class NullSession implements ClientSession {

    private final long id;
    private final Role role;
    long messages;
    /** Where its agent was in the last perception sent, or null. */
    Vec3 seen;

    NullSession(long id, Role role) {
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
    public void send(ServerMessage message) {
        messages++;
    }

    /** Counted as its three messages, which the network threads would make from it (not this thread). */
    @Override
    public void send(Percept percept) {
        messages += 3;
        seen = percept.position();
    }

    @Override
    public void send(EncodedLine line) {
        messages++;
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
