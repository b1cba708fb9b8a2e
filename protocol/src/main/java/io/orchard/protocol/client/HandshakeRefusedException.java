package io.orchard.protocol.client;

import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.io.IOException;

/**
 * The server answered a {@code Hello} with an {@code Error} instead of a {@code Welcome}, and closed
 * the connection: the cause of the {@link IOException} that {@link ProtocolConnection#connect}
 * throws then. Its {@link #error()} says why; a client may act on the code, for example try again
 * later after {@link ErrorCode#TOO_MANY_AGENTS}, but not after {@link ErrorCode#UNAUTHORIZED} or
 * {@link ErrorCode#VERSION_MISMATCH}, which the same hello will meet again.
 */
public final class HandshakeRefusedException extends IOException {

    private static final long serialVersionUID = 1L;

    /** The server's answer; not serialised with the exception. */
    private final transient ErrorMessage error;

    /** The server refused the hello with {@code error}. */
    public HandshakeRefusedException(ErrorMessage error) {
        super(error.code().wireName() + ": " + error.text());
        this.error = error;
    }

    /** The server's answer to the hello. */
    public ErrorMessage error() {
        return error;
    }

    /** Whether the same hello will be refused again: the token or the protocol version is wrong. */
    public boolean isFinal() {
        return error.code() == ErrorCode.UNAUTHORIZED || error.code() == ErrorCode.VERSION_MISMATCH;
    }
}
