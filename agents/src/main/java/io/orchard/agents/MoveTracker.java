package io.orchard.agents;

import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Point2;

/**
 * The agent's moves as its controller follows them: the latest one sent and, once it came, the
 * server's answer; and the walk under way, from an accepted move until its time is up or the
 * agent is seen standing still although it should walk (another agent stopped it). A rejected
 * move teaches the memory where the agent cannot go.
 */
final class MoveTracker {

    private MoveStatus last;
    private long lastSeq = -1;
    private MoveStatus walk;

    /** A move was sent under {@code seq} (-1 when it could not be) in this tick. */
    void sent(long seq, Point2 from, Point2 to, long tick) {
        last = new MoveStatus(from, to, tick, null, null, Double.NaN);
        lastSeq = seq;
    }

    /** The latest move sent and, once it came, the server's answer; null before the first. */
    @Nullable MoveStatus last() {
        return last;
    }

    /** Whether a move is under way: sent and not yet answered, or accepted and not yet over. */
    boolean walking() {
        return (last != null && !last.answered()) || walk != null;
    }

    /** Whether the agent is walking somewhere, as the walk animation shows. */
    boolean walkingSomewhere() {
        return walking() && last != null && !last.rejected() && last.from().distance(last.to()) > 1e-6;
    }

    /**
     * At the start of a turn: ends the walk when its time is up, or when a perception showed the
     * agent standing still although it should walk.
     */
    void update(long tick, double time, boolean perceived, boolean stoodStill) {
        if (walk == null) {
            return;
        }
        if (time >= walk.endsAt() - 1e-9) {
            walk = null;
        } else if (perceived && stoodStill && walk.tick() < tick - 1) {
            walk = null;
        }
    }

    /** The server answered {@code move}. */
    void answered(ActionResultMessage result, MoveMessage move, @Nullable WorldMemory memory, int tickRate) {
        if (result.seq() == lastSeq) {
            answeredLast(result, memory, tickRate);
        } else if (result.outcome() == Outcome.REJECTED && memory != null) {
            memory.moveRejected(move.from().onGround(), move.to().onGround(), result.reason());
        }
    }

    private void answeredLast(ActionResultMessage result, @Nullable WorldMemory memory, int tickRate) {
        MoveStatus asked = last;
        double start = asked.tick() / (double) tickRate;
        if (result.outcome() == Outcome.REJECTED) {
            last = new MoveStatus(asked.from(), asked.to(), asked.tick(), Outcome.REJECTED, result.reason(), start);
            if (memory != null && result.reason() != null) {
                memory.moveRejected(asked.from(), asked.to(), result.reason());
            }
        } else {
            Point2 end = result.position() == null ? asked.to() : result.position().onGround();
            last = new MoveStatus(asked.from(), end, asked.tick(), result.outcome(), result.reason(),
                    start + result.duration());
            walk = result.duration() > 0 ? last : null;
        }
    }
}
