package io.orchard.examples;

/**
 * The command line was wrong: an unknown option, a missing value, a value of the wrong form. The
 * message names the bad argument and what was expected; the launcher prints it with a pointer to
 * the command's {@code --help} and exits with status 2.
 */
public final class UsageException extends Exception {

    private static final long serialVersionUID = 1L;

    public UsageException(String message) {
        super(message);
    }
}
