package io.orchard.server.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Who wants the game saved, and when: once at the end of a tick (a command, a timer), and after every
 * tick in which the scores changed and when the game ends, so that nothing collected is lost to a
 * crash. Used on the simulation's thread only.
 */
final class CheckpointRequests {

    private final List<Consumer<Checkpoint>> once = new ArrayList<>();
    private Consumer<Checkpoint> onScore;
    /** Whether the game's end was saved, so that it is saved once. */
    private boolean overSaved;

    void atTickEnd(Consumer<Checkpoint> to) {
        once.add(to);
    }

    void whenScored(Consumer<Checkpoint> to) {
        onScore = to;
    }

    /** A restored game that was over is saved as over already. */
    void restored(Phase phase) {
        overSaved = phase == Phase.OVER;
    }

    /** At the end of a tick, in which the scores changed or not, with the game now at {@code phase}. */
    void tickEnded(boolean scored, Phase phase, Supplier<Checkpoint> game) {
        take(scored || phase == Phase.OVER && !overSaved, phase, game);
    }

    /** After what clients sent was applied while no ticks pass. */
    void applied(Phase phase, Supplier<Checkpoint> game) {
        take(false, phase, game);
    }

    private void take(boolean scored, Phase phase, Supplier<Checkpoint> game) {
        boolean forScore = scored && onScore != null;
        if (once.isEmpty() && !forScore) {
            return;
        }
        Checkpoint checkpoint = game.get();
        if (forScore) {
            onScore.accept(checkpoint);
            overSaved = phase == Phase.OVER;
        }
        once.forEach(request -> request.accept(checkpoint));
        once.clear();
    }
}
