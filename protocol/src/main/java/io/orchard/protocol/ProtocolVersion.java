package io.orchard.protocol;

/**
 * The version of the wire protocol. A client names the version it speaks in its hello; the server
 * speaks every version from {@link #OLDEST} to {@link #CURRENT} and refuses others. Version 2 adds
 * what version 1 clients never see: the operator token in {@code Hello}, the agent's own seed in
 * {@code Registered} and the {@code KeepAlive} message. A version 1 client is served exactly as
 * before.
 */
public final class ProtocolVersion {

    /** The protocol version this library speaks, and the newest the server speaks. */
    public static final int CURRENT = 2;

    /** The oldest protocol version the server still speaks. */
    public static final int OLDEST = 1;

    private ProtocolVersion() {}

    /** Whether a server of this library speaks {@code version}. */
    public static boolean isSpoken(int version) {
        return version >= OLDEST && version <= CURRENT;
    }
}
