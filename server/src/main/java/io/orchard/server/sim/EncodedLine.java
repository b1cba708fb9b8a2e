package io.orchard.server.sim;

import io.orchard.protocol.message.ServerMessage;
import java.util.function.Function;

/**
 * A server message to be written to many clients, encoded once for all of them: encoding costs far
 * more than copying, so its bytes are shared by every connection. It is encoded by the first
 * network thread that writes it, not by the simulation's thread that hands it out, so that the
 * tick's broadcasts (a {@code Tick} for everyone, an {@code AgentMoved} for every step of every
 * agent) cost the simulation only the hand-over.
 */
public final class EncodedLine {

    private final ServerMessage message;
    /** Written once, whole, by whichever thread encodes first; read by the others. */
    private volatile byte[] bytes;

    /** A line for {@code message}, not yet encoded. */
    public EncodedLine(ServerMessage message) {
        this.message = message;
    }

    /** The message. */
    public ServerMessage message() {
        return message;
    }

    /**
     * Its line, newline included, as {@code encoder} writes it: encoded on the first call and shared
     * by the later ones, from any thread (two threads that ask at once may both encode it, to the
     * same bytes). Never modify the array.
     */
    public byte[] bytes(Function<ServerMessage, byte[]> encoder) {
        byte[] encoded = bytes;
        if (encoded == null) {
            encoded = encoder.apply(message);
            bytes = encoded;
        }
        return encoded;
    }
}
