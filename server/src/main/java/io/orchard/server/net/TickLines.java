package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.util.concurrent.FastThreadLocal;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Percept;
import java.util.List;

/**
 * Encodes what one client is sent in a tick, one line after the other, into one buffer, in the
 * forms the client reads: a broadcast is copied from its shared bytes, a perception
 * ({@link Percept}) becomes one lean line for a client that reads the lean form ({@link LeanLines})
 * and its three messages for the others (a perception handed over as its three messages becomes the
 * same lean line for a lean reader), the lines that make most of the traffic are written
 * directly ({@link FastLines}) and the rest by the codec, all into an array of the network thread
 * that goes to the buffer in one copy. It stops before an {@code AgentAdded} with a model's data,
 * which its caller writes from the copy every client shares.
 */
final class TickLines {

    private static final MessageCodec CODEC = new MessageCodec();

    /**
     * The array each network thread writes a client's lines into before handing them to the
     * client's buffer at once; kept from one client to the next, but not beyond this size, which a
     * world's snapshot for a viewer may pass.
     */
    private static final FastThreadLocal<LineBytes> LINES = new FastThreadLocal<>() {
        @Override
        protected LineBytes initialValue() {
            return new LineBytes(KEPT_BYTES / 16);
        }
    };

    private static final int KEPT_BYTES = 1 << 20;

    private TickLines() {}

    /**
     * Writes {@code messages} ({@link ServerMessage}s, {@link Percept}s and {@link EncodedLine}s) from index
     * {@code from} on, until the end or a message that {@link #carriesModel carries a model}.
     *
     * @return the index of the message it stopped at, or the number of messages
     */
    static int write(List<?> messages, int from, ClientForms forms, ByteBuf out) {
        LineBytes lines = LINES.get();
        lines.clear();
        try {
            for (int i = from; i < messages.size(); i++) {
                Object message = messages.get(i);
                if (message instanceof EncodedLine line) {
                    if (carriesModel(line.message())) {
                        return i;
                    }
                    lines.bytes(line.bytes(TickLines::encode));
                } else if (message instanceof Percept percept) {
                    if (forms.leanPerception()) {
                        LeanLines.write(percept, lines);
                    } else {
                        for (ServerMessage part : percept.messages()) {
                            plain(part, lines);
                        }
                    }
                } else {
                    ServerMessage plain = (ServerMessage) message;
                    if (carriesModel(plain)) {
                        return i;
                    }
                    if (forms.leanPerception() && plain instanceof PerceptionMessage seen && i + 2 < messages.size()
                            && messages.get(i + 1) instanceof LandmarkPerceptionMessage landmarks
                            && messages.get(i + 2) instanceof CastlePerceptionMessage castle) {
                        // A perception that came as its three messages (from a cluster's tick, say):
                        // the lean reader gets its one line all the same.
                        lines.bytes(CODEC.encodeLine(LeanPerceptionMessage.of(seen, landmarks, castle)));
                        i += 2;
                    } else {
                        plain(plain, lines);
                    }
                }
            }
            return messages.size();
        } finally {
            lines.writeTo(out);
            lines.clear();
            lines.shrink(KEPT_BYTES);
        }
    }

    /** A broadcast's line, encoded once for every client that gets it. */
    static byte[] encode(ServerMessage message) {
        LineBytes line = new LineBytes(256);
        if (!FastLines.write(message, line)) {
            return CODEC.encodeLine(message);
        }
        return line.toArray();
    }

    private static void plain(ServerMessage message, LineBytes lines) {
        if (!FastLines.write(message, lines)) {
            lines.bytes(CODEC.encodeLine(message));
        }
    }

    /** Whether the message is an {@code AgentAdded} whose model's data goes out from the shared copy. */
    static boolean carriesModel(ServerMessage message) {
        return message instanceof AgentAddedMessage added && ModelLines.carriesData(added);
    }
}
