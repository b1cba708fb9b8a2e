package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Version 2: the operator restarted the game ({@code GameControl restart}). The game before it is
 * over (its {@code GameOver} came first) and its agents have left the world; a new game of a new
 * world waits for agents, as a new server would, its clock at tick 0. A client plays it by
 * registering its agents again; a viewer is sent the new world's {@link WorldSnapshotMessage} next.
 *
 * @param tick the new game's current tick: 0
 * @param timeLimit the new game's length in simulated seconds
 */
public record NewGameMessage(long tick,
                             double timeLimit) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public NewGameMessage {
        Checks.nonNegative(tick, "tick");
        Checks.nonNegative(timeLimit, "timeLimit");
    }
}
