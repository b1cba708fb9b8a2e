package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.GameCommand;

/**
 * Starts, pauses or continues the game, as a teacher at a console or a viewer would.
 *
 * @param seq client-chosen sequence number
 * @param command what to do
 */
public record GameControlMessage(long seq,
                                 GameCommand command) implements ClientMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GameControlMessage {
        Checks.nonNegative(seq, "seq");
        Checks.present(command, "command");
    }
}
