package io.orchard.viewer.model;

import io.orchard.viewer.model.ModelException.Kind;
import java.util.function.Supplier;

/**
 * The running totals a parser checks against {@link ModelLimits} as it goes, so that a hostile
 * input is stopped at the first node, level or number over the limit rather than after it has
 * been read in full.
 */
public final class ParseBudget {

    private final ModelLimits limits;
    private int nodes;
    private int depth;
    private long values;

    /** An empty budget, with nothing counted yet, for one parse against {@code limits}. */
    public ParseBudget(ModelLimits limits) {
        this.limits = limits;
    }

    /** Refuses input larger than the limit before any parsing starts. */
    public static void checkSize(byte[] bytes, ModelLimits limits, String formatName)
            throws ModelException {
        if (bytes.length > limits.maxInputBytes()) {
            throw new ModelException(Kind.TOO_LARGE, formatName + " model of " + bytes.length
                    + " bytes exceeds the limit of " + limits.maxInputBytes() + " bytes");
        }
        if (bytes.length == 0) {
            throw new ModelException(Kind.MALFORMED, formatName + " model is empty (0 bytes)");
        }
    }

    /** Counts {@code count} more nodes (a {@code USE} counts the weight of what it repeats). */
    public void addNodes(int count, String where) throws ModelException {
        nodes += count;
        if (nodes > limits.maxNodes() || nodes < 0) {
            throw new ModelException(Kind.TOO_LARGE, where + ": the model has more than "
                    + limits.maxNodes() + " nodes (counting each USE in full)");
        }
    }

    /** The limits this budget counts against. */
    public ModelLimits limits() {
        return limits;
    }

    /** Enters one level of nesting. */
    public void enter(String where) throws ModelException {
        depth++;
        if (depth > limits.maxDepth()) {
            throw new ModelException(Kind.TOO_LARGE, where + ": nesting deeper than "
                    + limits.maxDepth() + " levels");
        }
    }

    /**
     * Completes a node read at the current depth and checks that, with the trees its
     * {@code USE}s repeat, it does not reach deeper than the limit either.
     */
    public void complete(SceneNode node, String where) throws ModelException {
        node.complete();
        checkHeight(node, depth, where);
    }

    /**
     * Checks that a node placed at nesting level {@code level} (1 for a top-level node) keeps
     * its whole tree within the depth limit: a {@code USE} may repeat a deep tree deep down.
     */
    public void checkHeight(SceneNode node, int level, String where) throws ModelException {
        if (level - 1 + node.height() > limits.maxDepth()) {
            throw new ModelException(Kind.TOO_LARGE, where + ": " + node.label()
                    + " nests deeper than " + limits.maxDepth() + " levels (counting the nodes"
                    + " USEs repeat)");
        }
    }

    /** Leaves one level of nesting. */
    public void exit() {
        depth--;
    }

    /** How many levels of nesting are open now. */
    public int depth() {
        return depth;
    }

    /**
     * Counts one more number in an array field; {@code where} is called only to word the error,
     * so the common case builds no message.
     */
    public void addValue(Supplier<String> where) throws ModelException {
        values++;
        if (values > limits.maxArrayValues()) {
            throw new ModelException(Kind.TOO_LARGE, where.get() + ": more than "
                    + limits.maxArrayValues() + " numbers in array fields");
        }
    }
}
