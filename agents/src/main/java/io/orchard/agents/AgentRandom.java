package io.orchard.agents;

import java.util.SplittableRandom;
import java.util.random.RandomGenerator;

/**
 * An agent's random numbers. They are drawn from a seed made from the agent's name until the
 * server gives the agent its own seed ({@code Registered.seed}, protocol version 2, derived from the
 * game's seed and the name), and from that seed after: an agent that draws from it plays the same
 * lockstep game every time, and differently in a game of another seed. Behaviours hold this object,
 * so the new seed reaches them too. Used on the controller's thread only.
 */
final class AgentRandom implements RandomGenerator {

    private SplittableRandom source;

    AgentRandom(long seed) {
        source = new SplittableRandom(seed);
    }

    /** Draws from {@code seed} from now on. */
    void reseed(long seed) {
        source = new SplittableRandom(seed);
    }

    @Override
    public long nextLong() {
        return source.nextLong();
    }
}
