package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * A game starts: the seed that made the world, how much fruit there is and the time limit.
 *
 * @param tick the tick it started in
 * @param seed the world's seed, to repeat the game
 * @param fruitCount fruit in the world
 * @param timeLimit the game's length in simulated seconds
 */
public record GameStartedMessage(long tick,
                                 long seed,
                                 int fruitCount,
                                 double timeLimit) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GameStartedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.nonNegative(fruitCount, "fruitCount");
        Checks.nonNegative(timeLimit, "timeLimit");
    }
}
