package io.orchard.server.sim;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Score;
import java.util.List;

/**
 * Hears what happens in a game, for programs that embed the server. Called on the simulation's
 * thread: return quickly and hand long work elsewhere. Every method does nothing by default.
 */
public interface GameListener {

    /** The game started. */
    default void gameStarted(long seed, int fruitCount, double timeLimit) {}

    /** An agent entered the world. */
    default void agentJoined(String agent) {}

    /** An agent left the world (it unregistered or its connection closed). */
    default void agentLeft(String agent, String reason) {}

    /** An agent collected a fruit. */
    default void fruitEaten(String agent, String fruit, FruitKind kind, double time) {}

    /** The game ended; the ranking lists every agent that played, best first. */
    default void gameOver(String reason, List<Score> ranking) {}

    /**
     * The operator restarted the game: the one before is over, and a new one of a world made from
     * {@code seed} waits for its agents.
     */
    default void newGame(long seed) {}

    /**
     * In lockstep, the game went on without a client's turn: it had not ended its setup when the
     * game started, or a tick's turn when the tick ended. A game with no missed turn is the same
     * every time its agents play its seed.
     */
    default void turnMissed(MissedTurn missed) {}

    /** A tick ended (called once per tick, after the world changed). */
    default void tickEnded(long tick, double time) {}
}
