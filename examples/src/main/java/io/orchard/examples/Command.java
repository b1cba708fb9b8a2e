package io.orchard.examples;

import io.orchard.protocol.cli.UsageException;

import java.io.PrintStream;
import java.util.List;

/**
 * One subcommand of the {@link Orchard} launcher, such as {@code ./orchard protocol-schema}. To add
 * a subcommand, implement this interface in a small class and list an instance in
 * {@link Orchard#COMMANDS}; the launcher then lists it in its help, answers its {@code --help} with
 * {@link #help()} and turns a {@link UsageException} into exit status 2.
 *
 * <p>A command writes to the streams it is given rather than to {@code System.out}, so that a test
 * can run it and read what it printed.
 */
public interface Command {

    /** The word that selects the command on the command line, e.g. {@code protocol-schema}. */
    String name();

    /** One line for the launcher's list of commands, without a full stop. */
    String summary();

    /** The command's help: a usage line, what it does and its options, ending with a newline. */
    String help();

    /**
     * Runs the command.
     *
     * @param args the arguments after the command's name; never contains {@code --help}, which
     *             the launcher answers itself
     * @param out  where the command's results go
     * @param err  where diagnostics go
     * @return the exit status: 0 for success, 1 for a failure the message on {@code err} explains
     * @throws UsageException when the arguments are wrong; its message names the bad argument and
     *                        what was expected
     * @throws Exception      on any other failure; the launcher prints its message and exits with 1
     */
    int run(List<String> args, PrintStream out, PrintStream err) throws Exception;
}
