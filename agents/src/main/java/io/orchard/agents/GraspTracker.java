package io.orchard.agents;

import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.value.Nullable;

/** The agent's latest grasp as its controller follows it: sent and, once it came, the server's answer. */
final class GraspTracker {

    private GraspStatus last;
    private long lastSeq = -1;

    /** A grasp of {@code fruitId} was sent under {@code seq} (-1 when it could not be) in this tick. */
    void sent(long seq, String fruitId, long tick) {
        last = new GraspStatus(fruitId, tick, false, false, null);
        lastSeq = seq;
    }

    /** A grasp of {@code fruitId} was not sent, for this reason: it failed at once. */
    void refused(String fruitId, long tick, String reason) {
        last = new GraspStatus(fruitId, tick, true, false, reason);
        lastSeq = -1;
    }

    /** The latest grasp sent and, once it came, the server's answer; null before the first. */
    @Nullable GraspStatus last() {
        return last;
    }

    /** The server answered a grasp; only the answer to the latest changes what {@link #last()} says. */
    void answered(GraspResultMessage result) {
        if (result.seq() == lastSeq) {
            last = new GraspStatus(result.fruit(), last.tick(), true, result.success(), result.reason());
        }
    }
}
