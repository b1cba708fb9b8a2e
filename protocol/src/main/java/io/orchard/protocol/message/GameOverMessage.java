package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Score;

import java.util.List;

/**
 * The game is over: the fruit is gone or the time is up.
 *
 * @param tick the last tick
 * @param reason why it ended
 * @param ranking every agent that played, best first
 */
public record GameOverMessage(long tick,
                              String reason,
                              List<Score> ranking) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GameOverMessage {
        Checks.nonNegative(tick, "tick");
        Checks.text(reason, "reason");
        ranking = Checks.list(ranking, "ranking");
    }
}
