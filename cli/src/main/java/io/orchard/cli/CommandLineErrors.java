package io.orchard.cli;

import java.io.PrintStream;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.IParameterExceptionHandler;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * How a command answers what goes wrong: a wrong command line with
 * {@code orchard <command>: <what is wrong>} and exit status 2, naming the option, the value and
 * what was expected; a command that fails with {@code orchard <command>: <why>} and status 1.
 */
public final class CommandLineErrors implements IParameterExceptionHandler, IExecutionExceptionHandler {

    /** The exit status of a command that ran and failed. */
    public static final int FAILED = 1;
    /** The exit status of a wrong command line. */
    public static final int USAGE = 2;

    private final PrintStream err;

    /** Answers on {@code err}. */
    public CommandLineErrors(PrintStream err) {
        this.err = err;
    }

    /** Runs {@code line} on {@code args}, printing errors to {@code err}; returns the exit status. */
    public static int execute(CommandLine line, List<String> args, PrintStream err) {
        CommandLineErrors errors = new CommandLineErrors(err);
        return line.setParameterExceptionHandler(errors).setExecutionExceptionHandler(errors)
                .execute(args.toArray(String[]::new));
    }

    /** Prints what is wrong, any suggestions, and where the options are explained; returns {@link #USAGE}. */
    @Override
    public int handleParseException(ParameterException e, String[] args) {
        String name = e.getCommandLine().getCommandSpec().qualifiedName();
        err.println(name + ": " + describe(e));
        UnmatchedArgumentException.printSuggestions(e, err);
        err.println("Run ./" + name + " --help for its options.");
        return USAGE;
    }

    /** Prints why the command failed, with the stack trace of a defect; returns {@link #FAILED}. */
    @Override
    public int handleExecutionException(Exception e, CommandLine failed, ParseResult parsed) {
        err.println(failed.getCommandSpec().qualifiedName() + ": " + (e.getMessage() == null ? e : e.getMessage()));
        if (e instanceof RuntimeException) {
            e.printStackTrace(err); // a defect rather than a condition the message explains
        }
        return FAILED;
    }

    /** What is wrong with a command line, as a phrase to follow "orchard <command>: ". */
    static String describe(ParameterException e) {
        if (e instanceof UnmatchedArgumentException unmatched && !unmatched.isUnknownOption()) {
            List<String> args = unmatched.getUnmatched();
            return "unexpected argument" + (args.size() == 1 ? " " : "s ")
                    + String.join(", ", args.stream().map(arg -> "'" + arg + "'").toList()) + " (options start with --)";
        }
        String message = e.getMessage();
        return message.isEmpty() ? message : Character.toLowerCase(message.charAt(0)) + message.substring(1);
    }
}
