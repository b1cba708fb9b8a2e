package io.orchard.protocol;

/**
 * The version of the wire protocol. A client names the version it speaks in its hello; the server
 * refuses versions it does not speak. The number grows when a change would break existing clients;
 * adding an optional field or a new message type does not change it, since decoders ignore fields
 * they do not know.
 */
public final class ProtocolVersion {

    /** The protocol version this library speaks. */
    public static final int CURRENT = 1;

    private ProtocolVersion() {}
}
