package io.orchard.agents.behaviour;

import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Point2;

/**
 * The agent's latest move as its controller knows it.
 *
 * @param from    where it started
 * @param to      where it was asked to end (where it stops, once the server said it is blocked)
 * @param tick    the tick it was sent in
 * @param outcome the server's answer; null until it came
 * @param reason  why it was blocked or rejected; null otherwise
 * @param endsAt  the simulated time at which the walk ends, once accepted or blocked
 */
public record MoveStatus(Point2 from, Point2 to, long tick, @Nullable Outcome outcome, @Nullable String reason,
                         double endsAt) {

    /** Whether the server has answered. */
    public boolean answered() {
        return outcome != null;
    }

    /** Whether the server refused the move. */
    public boolean rejected() {
        return outcome == Outcome.REJECTED;
    }

    /** Whether another agent cut the move short. */
    public boolean blocked() {
        return outcome == Outcome.BLOCKED;
    }
}
