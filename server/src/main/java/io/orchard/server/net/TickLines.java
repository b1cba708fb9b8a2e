package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Percept;
import java.util.List;

/**
 * Encodes what one client is sent in a tick, one line after the other, into one buffer, in the
 * forms the client reads: a broadcast is copied from its shared bytes, a perception
 * ({@link Percept}) becomes one lean line for a client that reads the lean form ({@link LeanLines})
 * and its three messages for the others, the lines that make most of the traffic are written
 * directly ({@link FastLines}) and the rest by the codec. It stops before an {@code AgentAdded} with a model's data, which its caller writes from the
 * copy every client shares. Stateless.
 */
final class TickLines {

    private static final MessageCodec CODEC = new MessageCodec();

    private TickLines() {}

    /**
     * Writes {@code messages} ({@link ServerMessage}s, {@link Percept}s and {@link EncodedLine}s) from index
     * {@code from} on, until the end or a message that {@link #carriesModel carries a model}.
     *
     * @return the index of the message it stopped at, or the number of messages
     */
    static int write(List<?> messages, int from, ClientForms forms, ByteBuf out) {
        for (int i = from; i < messages.size(); i++) {
            Object message = messages.get(i);
            if (message instanceof EncodedLine line) {
                if (carriesModel(line.message())) {
                    return i;
                }
                out.writeBytes(line.bytes(TickLines::encode));
            } else if (message instanceof Percept percept) {
                if (forms.leanPerception()) {
                    LeanLines.write(percept, out);
                } else {
                    for (ServerMessage part : percept.messages()) {
                        plain(part, out);
                    }
                }
            } else {
                ServerMessage plain = (ServerMessage) message;
                if (carriesModel(plain)) {
                    return i;
                }
                plain(plain, out);
            }
        }
        return messages.size();
    }

    /** A broadcast's line, encoded once for every client that gets it. */
    static byte[] encode(ServerMessage message) {
        ByteBuf out = Unpooled.buffer(256);
        if (!FastLines.write(message, out)) {
            return CODEC.encodeLine(message);
        }
        return ByteBufUtil.getBytes(out);
    }

    private static void plain(ServerMessage message, ByteBuf out) {
        if (!FastLines.write(message, out)) {
            out.writeBytes(CODEC.encodeLine(message));
        }
    }

    /** Whether the message is an {@code AgentAdded} whose model's data goes out from the shared copy. */
    static boolean carriesModel(ServerMessage message) {
        return message instanceof AgentAddedMessage added && ModelLines.carriesData(added);
    }
}
