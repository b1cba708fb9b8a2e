package io.orchard.server;

import io.orchard.protocol.value.Score;
import io.orchard.server.sim.GameListener;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The ranking of the current game, to wait for: a future that completes when the game is over, and
 * a new one for each game the operator restarts.
 */
final class GameResults implements GameListener {

    private volatile CompletableFuture<List<Score>> current = new CompletableFuture<>();

    /** Completes with the ranking when the current game is over. */
    CompletableFuture<List<Score>> current() {
        return current;
    }

    @Override
    public void gameOver(String reason, List<Score> ranking) {
        current.complete(ranking);
    }

    @Override
    public void newGame(long seed) {
        current = new CompletableFuture<>();
    }

    /** No game will end any more: the server closed. */
    void cancel() {
        current.cancel(false);
    }
}
