package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Something a client sent was wrong. The text names the bad field and value; the code is stable
 * and listed in {@link ErrorCode}. The connection stays open unless the text says it closes.
 *
 * @param seq the sequence number of the message it answers, 0 when it answers none
 * @param code what kind of error
 * @param text what was wrong, naming the field and the value
 */
public record ErrorMessage(long seq,
                           ErrorCode code,
                           String text) implements ServerMessage, Reply {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public ErrorMessage {
        Checks.nonNegative(seq, "seq");
        Checks.present(code, "code");
        Checks.text(text, "text");
    }
}
