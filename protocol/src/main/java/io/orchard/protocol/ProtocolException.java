package io.orchard.protocol;

import io.orchard.protocol.message.ErrorCode;

/**
 * A line that is not a valid message. The only exception {@link MessageCodec} throws when decoding;
 * its {@linkplain #code() code} and {@linkplain #getMessage() message} are what the server sends
 * back in an {@code ErrorMessage}, so the message names the field and the bad value, and its
 * {@linkplain #seq() seq} is the one the error echoes.
 */
public final class ProtocolException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final ErrorCode code;
    private final long seq;

    /** A failure with its stable code and a message that names the bad value and what was expected. */
    public ProtocolException(ErrorCode code, String message) {
        this(code, message, 0);
    }

    /** A failure of a line whose {@code seq} could be read: {@code seq}, or 0 when it could not. */
    public ProtocolException(ErrorCode code, String message, long seq) {
        super(message);
        this.code = code;
        this.seq = seq;
    }

    /** The stable error code for this failure. */
    public ErrorCode code() {
        return code;
    }

    /**
     * The {@code seq} of the bad line, for the error to echo: a top-level {@code "seq"} that is an
     * integer from 0 to 2<sup>63</sup>&minus;1, found before the line stops being JSON; 0 when there is none.
     */
    public long seq() {
        return seq;
    }
}
