package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Nullable;

/**
 * Starts, pauses, continues or restarts the game, as a teacher at a console or a viewer would.
 *
 * @param seq client-chosen sequence number
 * @param command what to do
 * @param seed with {@code restart} only (version 2): the seed of the new game's world; absent, the
 *             same seed as the game that ends
 */
public record GameControlMessage(long seq,
                                 GameCommand command,
                                 @Nullable Long seed) implements ClientMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GameControlMessage {
        Checks.nonNegative(seq, "seq");
        Checks.present(command, "command");
        if (seed != null && command != GameCommand.RESTART) {
            throw new IllegalArgumentException("seed goes only with the command 'restart', was given with '"
                    + command.wireName() + "'");
        }
    }

    /** A command without a seed. */
    public GameControlMessage(long seq, GameCommand command) {
        this(seq, command, null);
    }
}
