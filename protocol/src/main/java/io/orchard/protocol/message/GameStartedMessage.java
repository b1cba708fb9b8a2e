package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;

/**
 * A game starts: how much fruit there is, the time limit and, for viewers, the seed that made the
 * world. Every client hears it once: when the game starts, or, connecting later, right after its
 * welcome.
 *
 * @param tick the tick it started in
 * @param seed the world's seed, to repeat the game; sent to viewers only, since an agent that knew
 *             it could compute the whole world
 * @param fruitCount fruit in the world
 * @param timeLimit the game's length in simulated seconds
 */
public record GameStartedMessage(long tick,
                                 @Nullable Long seed,
                                 int fruitCount,
                                 double timeLimit) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public GameStartedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.nonNegative(fruitCount, "fruitCount");
        Checks.nonNegative(timeLimit, "timeLimit");
    }

    /** A start with the world's seed, as viewers hear it. */
    public GameStartedMessage(long tick, long seed, int fruitCount, double timeLimit) {
        this(tick, Long.valueOf(seed), fruitCount, timeLimit);
    }

    /** The same start without the world's seed, as agent clients hear it. */
    public GameStartedMessage withoutSeed() {
        return seed == null ? this : new GameStartedMessage(tick, null, fruitCount, timeLimit);
    }
}
