package io.orchard.server.sim;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ServerMessage;

/**
 * A server message encoded once, to be written to many clients: encoding costs far more than
 * copying, so a broadcast is encoded on one thread and its bytes shared by every connection.
 *
 * @param message the message
 * @param bytes   its line, newline included; never modified after construction
 */
public record EncodedLine(ServerMessage message, byte[] bytes) {

    /** Encodes a message for broadcasting. */
    public static EncodedLine of(MessageCodec codec, ServerMessage message) {
        return new EncodedLine(message, codec.encodeLine(message));
    }
}
