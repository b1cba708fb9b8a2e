package io.orchard.viewer.model;

/**
 * An agent model that cannot be used, or a request a model cannot honour. Agent models arrive as
 * untrusted bytes from any client, so every way a model can be wrong (malformed, too large,
 * hostile, naming something it does not contain) ends here and nowhere else: loading never throws
 * another exception type, runs out of memory or hangs on bad input.
 *
 * <p>The exception is checked on purpose: a viewer that forgets to handle it would let one bad
 * model stop the render thread. The usual reaction is to log {@link #getMessage()} and show
 * {@link BodyModels#placeholder} instead. The message names the problem, the node (type and DEF
 * name), the field and the offending value, and where known the line and column.
 */
public final class ModelException extends Exception {

    private static final long serialVersionUID = 1L;

    /** What kind of problem it is, for callers that react differently to each. */
    public enum Kind {
        /** Not well-formed: truncated, a syntax error, a wrong number of values. */
        MALFORMED,
        /** A value of the wrong type or out of range: letters or NaN where a number belongs. */
        BAD_VALUE,
        /** A DEF, USE, ROUTE, joint or animation name that the model does not contain. */
        UNKNOWN_NAME,
        /** Over one of the {@link ModelLimits}: bytes, nodes, depth, values, texture size. */
        TOO_LARGE,
        /** An attempt to reach outside the model: XML entities, external files or URLs. */
        UNSAFE,
        /** A valid input this loader does not read: VRML 1.0, another glTF version. */
        UNSUPPORTED
    }

    private final Kind kind;

    /** A problem of the given kind, with a message that says what and where. */
    public ModelException(Kind kind, String message) {
        super(message);
        this.kind = kind;
    }

    /** A problem of the given kind caused by another exception, such as a parser's. */
    public ModelException(Kind kind, String message, Throwable cause) {
        super(message, cause);
        this.kind = kind;
    }

    /** The kind of problem. */
    public Kind kind() {
        return kind;
    }
}
