package io.orchard.protocol.cli;

/** A command line that cannot be run: the message says which option or value is wrong and why. */
public final class UsageException extends Exception {

    private static final long serialVersionUID = 1L;

    /** A command line that cannot be run, with {@code message} saying which option or value is wrong and why. */
    public UsageException(String message) {
        super(message);
    }
}
