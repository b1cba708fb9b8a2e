package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Says that the client has sent all its actions for a tick. In lockstep mode the server advances
 * the clock as soon as every agent's client has ended its turn (or the tick's deadline passes).
 *
 * @param seq client-chosen sequence number
 * @param tick the tick whose turn ends
 */
public record EndTurnMessage(long seq,
                             long tick) implements ClientMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public EndTurnMessage {
        Checks.nonNegative(seq, "seq");
        Checks.nonNegative(tick, "tick");
    }
}
