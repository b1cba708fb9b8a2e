package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Score;

import java.util.List;

/**
 * The scores changed.
 *
 * @param tick the tick it changed in
 * @param scores every agent's score, best first
 */
public record ScoreUpdateMessage(long tick,
                                 List<Score> scores) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public ScoreUpdateMessage {
        Checks.nonNegative(tick, "tick");
        scores = Checks.list(scores, "scores");
    }
}
