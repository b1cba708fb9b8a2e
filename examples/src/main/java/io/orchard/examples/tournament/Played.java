package io.orchard.examples.tournament;

import io.orchard.server.sim.MissedTurn;
import java.util.List;

/**
 * One game of a tournament as it was played.
 *
 * @param game         the game's number, from 1
 * @param seed         the seed of its world
 * @param fruitAtStart the fruit in the world when it started
 * @param seconds      its length in simulated seconds (shorter than the limit when the fruit ran out)
 * @param rows         each agent's result, in the line-up's order
 * @param moves        the moves the agents sent
 * @param refused      of them, the moves refused because something in the world was in the way
 * @param missed       the lockstep turns the game went on without (none in a game that repeats exactly)
 */
record Played(int game, long seed, int fruitAtStart, double seconds, List<Result> rows, long moves, long refused,
              List<MissedTurn> missed) {

    Played {
        rows = List.copyOf(rows);
        missed = List.copyOf(missed);
    }

    /** The fruit the agents collected together. */
    int collected() {
        return rows.stream().mapToInt(Result::fruit).sum();
    }

    /** The turns missed by the clients of {@code agent}. */
    List<MissedTurn> missedBy(String agent) {
        return missed.stream().filter(m -> m.agents().contains(agent)).toList();
    }
}
