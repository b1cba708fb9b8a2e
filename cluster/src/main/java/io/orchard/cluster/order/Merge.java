package io.orchard.cluster.order;

import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Recorder.Audience;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Puts the lines that the parts of a world said in a step in the single server's order, by key,
 * and then writes them to the recording and to the clients: each message sent to one client to that
 * client, each broadcast to every client of its audience, encoded once for all of them, as the single
 * server's outbox does. A client hears broadcasts from the line where it joined their audiences
 * ({@link KeyedLine#joining}) on; messages to it alone from when it connected.
 */
public final class Merge {

    /** Every client connected, by number. */
    private final Map<Long, ClientSession> connected = new TreeMap<>();
    private final Map<Long, ClientSession> all = new TreeMap<>();
    private final Map<Long, ClientSession> viewers = new TreeMap<>();
    private final Map<Long, ClientSession> agentClients = new TreeMap<>();
    private Recorder recorder;

    /** Merges into {@code recorder}. */
    public Merge(Recorder recorder) {
        this.recorder = recorder;
    }

    /** A client connected: messages to it alone reach it from now on. */
    public void connected(ClientSession session) {
        connected.put(session.id(), session);
    }

    /** A connected client joins the audiences of broadcasts now. */
    public void join(ClientSession session) {
        all.put(session.id(), session);
        (session.role() == Role.VIEWER ? viewers : agentClients).put(session.id(), session);
    }

    /** A client left. */
    public void leave(ClientSession session) {
        connected.remove(session.id());
        all.remove(session.id());
        viewers.remove(session.id());
        agentClients.remove(session.id());
    }

    /** Writes the lines of one step, from every part, in order. */
    public void write(Collection<KeyedLine> said) {
        List<KeyedLine> lines = new ArrayList<>(said);
        lines.sort((a, b) -> a.key().compareTo(b.key()));
        for (KeyedLine line : lines) {
            line.writeTo(recorder);
            if (line.target() != null) {
                ClientSession to = connected.get(line.target().id());
                if (to != null && line.joins()) {
                    join(to);
                } else if (to != null) {
                    to.send(line.sent());
                }
            } else if (line.to() != null && line.to() != Audience.CLIENT) {
                Map<Long, ClientSession> to = switch (line.to()) {
                    case VIEWERS -> viewers;
                    case AGENTS -> agentClients;
                    default -> all;
                };
                if (!to.isEmpty()) {
                    EncodedLine encoded = new EncodedLine((ServerMessage) line.message());
                    to.values().forEach(session -> session.send(encoded));
                }
            }
        }
    }

    /** Sends what the clients have queued and writes out the recording. */
    public void flush() {
        connected.values().forEach(ClientSession::flush);
        recorder.flush();
    }

    /** Records nothing more: the game is over. */
    public void stopRecording() {
        recorder.flush();
        recorder = Recorder.NONE;
    }
}
