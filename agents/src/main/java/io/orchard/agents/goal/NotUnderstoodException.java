package io.orchard.agents.goal;

/**
 * An instruction an {@link Interpreter} could not read. Its message says what was not understood
 * and what would have been, so that the agent can answer with it.
 */
public final class NotUnderstoodException extends Exception {

    private static final long serialVersionUID = 1L;

    /** @param message what was not understood and what is expected */
    public NotUnderstoodException(String message) {
        super(message);
    }
}
