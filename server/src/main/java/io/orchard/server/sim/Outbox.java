package io.orchard.server.sim;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.Recorder.Audience;
import java.util.Map;
import java.util.TreeMap;

/**
 * Everything the simulation says, and who hears it: the connected clients, by kind, and the record
 * of the game. It keeps the tick and the simulated time that the game is at, since every message is
 * recorded with them.
 *
 * <p>Messages queue in the sessions and in the recorder until {@link #flush()}, at the end of every
 * half tick. Clients are kept by their connection number, so a broadcast reaches them in the order
 * they connected.
 */
final class Outbox {

    /** Immutable and costly to build: one for every simulation. */
    private static final MessageCodec CODEC = new MessageCodec();

    private final Map<Long, ClientSession> sessions = new TreeMap<>();
    private final Map<Long, ClientSession> viewers = new TreeMap<>();
    private final Map<Long, ClientSession> agentClients = new TreeMap<>();
    /** Where the game is recorded; nothing after the game's end, so that the same game gives the same record. */
    private Recorder recorder;
    /** Read by the network threads for their welcomes. */
    private volatile long tick;
    private double time;

    Outbox(Recorder recorder) {
        this.recorder = recorder;
    }

    /** The tick that runs now (the next to begin, between ticks). */
    long tick() {
        return tick;
    }

    /** Simulated seconds since the game started. */
    double time() {
        return time;
    }

    /** Sets the clock that stamps what is sent from now on. */
    void at(long tick, double time) {
        this.tick = tick;
        this.time = time;
    }

    void join(ClientSession session) {
        sessions.put(session.id(), session);
        (session.role() == Role.VIEWER ? viewers : agentClients).put(session.id(), session);
    }

    /** Forgets a client; false if it was not connected. */
    boolean leave(ClientSession session) {
        if (sessions.remove(session.id()) == null) {
            return false;
        }
        viewers.remove(session.id());
        agentClients.remove(session.id());
        return true;
    }

    /** Whether the client is connected, so that what it sends counts. */
    boolean connected(ClientSession session) {
        return sessions.containsKey(session.id());
    }

    /** Records a client message that the simulation is about to apply. */
    void accepted(ClientSession session, ClientMessage message) {
        recorder.accepted(tick, time, session.id(), withoutSecrets(message));
    }

    void send(ClientSession session, ServerMessage message) {
        recorder.sent(tick, time, Audience.CLIENT, session.id(), withoutSecrets(message));
        session.send(message);
    }

    /** Sends to every client of the audience, encoding the message once for all of them. */
    void broadcast(ServerMessage message, Audience audience) {
        recorder.sent(tick, time, audience, 0, message);
        Map<Long, ClientSession> to = switch (audience) {
            case ALL -> sessions;
            case VIEWERS -> viewers;
            case AGENTS -> agentClients;
            case CLIENT -> Map.of();
        };
        if (to.isEmpty()) {
            return;
        }
        EncodedLine line = EncodedLine.of(CODEC, message);
        for (ClientSession session : to.values()) {
            session.send(line);
        }
    }

    /** Sends what the clients have queued and writes out the record. */
    void flush() {
        sessions.values().forEach(ClientSession::flush);
        recorder.flush();
    }

    /** Records nothing more: the game is over. */
    void stopRecording() {
        recorder = Recorder.NONE;
    }

    /** Recordings may be shared: they keep no resume token. */
    private static Message withoutSecrets(Message message) {
        if (message instanceof RegisteredMessage r && r.resumeToken() != null) {
            return new RegisteredMessage(r.seq(), r.agent(), r.body(), r.position(), r.heading(), null);
        }
        if (message instanceof RegisterMessage r && r.resumeToken() != null) {
            return new RegisterMessage(r.seq(), r.name(), r.body(), r.model(), null);
        }
        return message;
    }
}
