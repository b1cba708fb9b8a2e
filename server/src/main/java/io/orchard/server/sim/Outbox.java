package io.orchard.server.sim;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.KeepAliveMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.Recorder.Audience;
import java.util.HashMap;
import java.util.List;
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
 *
 * <p>The record is a function of the game, not of the order in which clients came: clients are
 * named in it by labels ({@link Recorder}); what a viewer is sent to catch up with the game when
 * it connects, and keep-alives, are left out (the broadcasts already hold the game); and until the
 * game starts, lines are held back and then written client by client in the order of their labels
 * ({@link HeldRecord}).
 */
final class Outbox {

    private final Map<Long, ClientSession> sessions = new TreeMap<>();
    private final Map<Long, ClientSession> viewers = new TreeMap<>();
    private final Map<Long, ClientSession> agentClients = new TreeMap<>();
    /** Agents' clients by the name of the first agent they asked to register, as the record names them. */
    private final Map<Long, String> labels = new HashMap<>();
    /** The client whose message is being applied: what is recorded meanwhile is its doing. */
    private ClientSession cause;
    /** Lines held until the game starts; null once it has. */
    private HeldRecord held = new HeldRecord();
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

    /** Every connected client, in the order they connected. */
    List<ClientSession> clients() {
        return List.copyOf(sessions.values());
    }

    /** Forgets a client; false if it was not connected. */
    boolean leave(ClientSession session) {
        if (sessions.remove(session.id()) == null) {
            return false;
        }
        viewers.remove(session.id());
        agentClients.remove(session.id());
        labels.remove(session.id());
        return true;
    }

    /** The client whose message is applied from now on (null: the server's own work). */
    void from(ClientSession session) {
        cause = session;
    }

    /** Names a client in the record as another part of the world named it: by its first agent's name. */
    void labelled(ClientSession session, String label) {
        if (session.role() == Role.AGENT) {
            labels.put(session.id(), label);
        }
    }

    /** How the record names a client. */
    String label(ClientSession session) {
        return session.role() == Role.VIEWER ? "viewer" : labels.getOrDefault(session.id(), "agent");
    }

    /** Whether the client is connected, so that what it sends counts. */
    boolean connected(ClientSession session) {
        return sessions.containsKey(session.id());
    }

    /** Records a client message that the simulation is about to apply. */
    void accepted(ClientSession session, ClientMessage message) {
        if (message instanceof KeepAliveMessage) {
            return; // it says only that the client is there, whenever its clock says so
        }
        if (message instanceof RegisterMessage register && session.role() == Role.AGENT) {
            labels.putIfAbsent(session.id(), register.name());
        }
        record(null, session, withoutSecrets(message), null);
    }

    void send(ClientSession session, ServerMessage message) {
        record(Audience.CLIENT, session, withoutSecrets(message), null);
        session.send(message);
    }

    /** Sends a perception, recorded (when anything is) as its three messages. */
    void send(ClientSession session, Percept percept) {
        if (recording()) {
            for (ServerMessage message : percept.messages()) {
                record(Audience.CLIENT, session, message, null);
            }
        }
        session.send(percept);
    }

    /** Whether what is sent is recorded: made into messages for the record, which costs for a perception. */
    private boolean recording() {
        return held != null || recorder != Recorder.NONE;
    }

    /** Sends without recording: what a client is told only to catch up with what the record already holds. */
    void catchUp(ClientSession session, ServerMessage message) {
        session.send(message);
    }

    /** Records a lockstep turn that the game went on without. */
    void missed(ClientSession session, MissedTurn missed) {
        record(null, session, null, missed);
    }

    /** Sends to every client of the audience, encoded once for all by the network thread that writes it first. */
    void broadcast(ServerMessage message, Audience audience) {
        record(audience, null, message, null);
        Map<Long, ClientSession> to = switch (audience) {
            case ALL -> sessions;
            case VIEWERS -> viewers;
            case AGENTS -> agentClients;
            case CLIENT -> Map.of();
        };
        if (to.isEmpty()) {
            return;
        }
        EncodedLine line = new EncodedLine(message);
        for (ClientSession session : to.values()) {
            session.send(line);
        }
    }

    /** Sends what the clients have queued and writes out the record. */
    void flush() {
        sessions.values().forEach(ClientSession::flush);
        recorder.flush();
    }

    /**
     * Writes out the record but leaves what the clients have queued for the next {@link #flush()},
     * which sends it first: for the end of a tick that the next tick's start follows at once, so
     * that a client gets both in one write.
     */
    void flushRecord() {
        recorder.flush();
    }

    /**
     * From now on records to {@code to} and sends to no client of its own: for a part of a game
     * whose caller records what it says and hands it to the clients itself ({@link Referee}).
     * The clients' labels are kept.
     */
    void recordOnly(Recorder to) {
        release();
        recorder = to;
        sessions.clear();
        viewers.clear();
        agentClients.clear();
    }

    /** Forgets how the record names a client that left. */
    void forgetLabel(ClientSession session) {
        labels.remove(session.id());
    }

    /** Records nothing more: the game is over. */
    void stopRecording() {
        release();
        recorder = Recorder.NONE;
    }

    /** Writes what was held back while the game waited to start, and holds nothing from now on. */
    void release() {
        if (held != null) {
            held.writeTo(recorder);
            held = null;
        }
    }

    /**
     * One recorder call: {@code to} null for a message accepted from {@code client}; {@code missed}
     * for a missed turn; else a message sent to the audience (to {@code client} alone for CLIENT).
     */
    private void record(Audience to, ClientSession client, Message message, MissedTurn missed) {
        if (!recording()) {
            return;
        }
        String label = client == null ? null : label(client);
        if (held != null) {
            held.add(cause != null ? cause : client, cause != null ? label(cause) : label, tick, time, to, label,
                    message, missed);
        } else if (missed != null) {
            recorder.missed(tick, time, label, missed);
        } else if (to == null) {
            recorder.accepted(tick, time, label, message);
        } else {
            recorder.sent(tick, time, to, label, message);
        }
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
