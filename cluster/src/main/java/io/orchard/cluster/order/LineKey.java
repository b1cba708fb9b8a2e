package io.orchard.cluster.order;

import java.util.Comparator;

/**
 * A line's place in the single server's order of a tick: the tick; its step ({@link Step}); within
 * the step, whose line it is (an agent's name, the rank of a client, the first claim of a fruit);
 * then the line's place among its cause's. Keys compare in that order.
 *
 * @param tick  the tick
 * @param step  the step of the tick
 * @param name  within the step: the agent's name (perceive, walk), the client's first agent's name
 *              (apply, missed; empty for a client without agents), or that of the first claim (grasp)
 * @param first within the step and name: the connection of a client without agents; while no tick
 *              passes, the number of what came
 * @param index within the client: the message's place among those it sent in the tick
 * @param line  the line's place among those its cause said
 */
public record LineKey(long tick, Step step, String name, long first, long index, int line)
        implements Comparable<LineKey> {

    /** The steps of a tick, in the single server's order (docs/protocol.md, 10.2). */
    public enum Step {
        /** What clients sent while no tick passes (before the tick of the key), in the order it came. */
        IDLE,
        /** The {@code Tick} to every client. */
        TICK,
        /** The perceptions, agent by agent in the order of their names. */
        PERCEIVE,
        /** What clients sent, client by client. */
        APPLY,
        /** Turns the tick went on without. */
        MISSED,
        /** The grasps, fruit by fruit in the order of their first requests. */
        GRASP,
        /** Walking agents stopped, in the order of their names. */
        WALK,
        /** The scores, when they changed. */
        SCORE,
        /** The end of the game. */
        END
    }

    private static final Comparator<LineKey> ORDER = Comparator.comparingLong(LineKey::tick)
            .thenComparing(LineKey::step).thenComparing(LineKey::name).thenComparingLong(LineKey::first)
            .thenComparingLong(LineKey::index).thenComparingInt(LineKey::line);

    /** The key of a step with no name: the step's lines come in the order said. */
    public static LineKey of(long tick, Step step) {
        return new LineKey(tick, step, "", 0, 0, 0);
    }

    /** The same place, for the {@code line}-th line said there. */
    public LineKey line(int number) {
        return new LineKey(tick, step, name, first, index, number);
    }

    /** The same cause in another step: a grasp's lines go where its request was applied. */
    public LineKey in(Step other) {
        return new LineKey(tick, other, name, first, index, 0);
    }

    @Override
    public int compareTo(LineKey other) {
        return ORDER.compare(this, other);
    }
}
