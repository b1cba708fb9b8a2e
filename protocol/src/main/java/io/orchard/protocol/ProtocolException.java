package io.orchard.protocol;

import io.orchard.protocol.message.ErrorCode;

/**
 * A line that is not a valid message. The only exception {@link MessageCodec} throws when decoding;
 * its {@linkplain #code() code} and {@linkplain #getMessage() message} are what the server sends
 * back in an {@code ErrorMessage}, so the message names the field and the bad value.
 */
public final class ProtocolException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final ErrorCode code;

    /** A failure with its stable code and a message that names the bad value and what was expected. */
    public ProtocolException(ErrorCode code, String message) {
        super(message);
        this.code = code;
    }

    /** The stable error code for this failure. */
    public ErrorCode code() {
        return code;
    }
}
