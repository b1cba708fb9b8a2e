package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Says "still here" when a client has nothing else to send (version 2): an agent's controller
 * that waits, or whose agent was told to stop, sends one at least every 30 s so that the server's
 * idle rule does not close its connection. It has no reply and no effect on the game.
 *
 * @param seq client-chosen sequence number
 */
public record KeepAliveMessage(long seq) implements ClientMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public KeepAliveMessage {
        Checks.nonNegative(seq, "seq");
    }
}
