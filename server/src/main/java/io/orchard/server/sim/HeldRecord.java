package io.orchard.server.sim;

import io.orchard.protocol.message.Message;
import io.orchard.server.sim.Recorder.Audience;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What is recorded while a game waits to start, held back and written when it starts: first the
 * server's own lines (the world), then each client's lines, with what they caused, client by client
 * in the order of the clients' labels (the names of their first agents). Clients register in
 * whatever order their threads and the network let them; the record does not show it.
 */
final class HeldRecord {

    /** One recorder call, kept until the start. */
    private record Line(long tick, double time, Audience to, String client, Message message, MissedTurn missed) {

        void writeTo(Recorder recorder) {
            if (missed != null) {
                recorder.missed(tick, time, client, missed);
            } else if (to == null) {
                recorder.accepted(tick, time, client, message);
            } else {
                recorder.sent(tick, time, to, client, message);
            }
        }
    }

    /** A client's lines, under the label it had when it last added one. */
    private static final class Client {
        final long id;
        final List<Line> lines = new ArrayList<>();
        String label;
        boolean agent;

        Client(long id) {
            this.id = id;
        }
    }

    private final List<Line> server = new ArrayList<>();
    private final Map<Long, Client> clients = new LinkedHashMap<>();

    /**
     * Keeps a line caused by {@code cause} (null: by the server itself), a client labelled
     * {@code label}; {@code to} null for a message accepted, {@code missed} non-null for a missed turn.
     */
    void add(ClientSession cause, String label, long tick, double time, Audience to, String client, Message message,
             MissedTurn missed) {
        Line line = new Line(tick, time, to, client, message, missed);
        if (cause == null) {
            server.add(line);
            return;
        }
        Client held = clients.computeIfAbsent(cause.id(), Client::new);
        held.label = label;
        held.agent = cause.role() == io.orchard.protocol.value.Role.AGENT;
        held.lines.add(line);
    }

    /**
     * Writes every line held: the server's, then viewers' in the order they connected, then agents'
     * clients by label (clients that share a label, having asked for the same name, by connection).
     */
    void writeTo(Recorder recorder) {
        server.forEach(line -> line.writeTo(recorder));
        List<Client> ordered = new ArrayList<>(clients.values());
        ordered.sort(Comparator.comparing((Client c) -> c.agent).thenComparing(c -> c.agent ? c.label : "")
                .thenComparingLong(c -> c.id));
        for (Client client : ordered) {
            client.lines.forEach(line -> line.writeTo(recorder));
        }
        server.clear();
        clients.clear();
    }
}
