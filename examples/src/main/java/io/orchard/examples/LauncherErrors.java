package io.orchard.examples;

import java.io.PrintStream;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.IParameterExceptionHandler;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * How the launcher answers what goes wrong: a wrong command line with
 * {@code orchard <command>: <what is wrong>} and exit status 2, naming the option, the value and
 * what was expected; a command that fails with {@code orchard <command>: <why>} and status 1.
 */
final class LauncherErrors implements IParameterExceptionHandler, IExecutionExceptionHandler {

    static final int FAILED = 1;
    static final int USAGE = 2;

    private final PrintStream err;

    LauncherErrors(PrintStream err) {
        this.err = err;
    }

    @Override
    public int handleParseException(ParameterException e, String[] args) {
        CommandLine failed = e.getCommandLine();
        if (failed.getParent() == null && e instanceof UnmatchedArgumentException unmatched) {
            return unknown(unmatched.getUnmatched().get(0), failed);
        }
        if (failed.getParent() == null && args.length == 2 && args[0].equals("help")) {
            return unknown(args[1], failed); // help of a command that does not exist
        }
        String name = failed.getCommandSpec().qualifiedName();
        err.println(name + ": " + describe(e));
        UnmatchedArgumentException.printSuggestions(e, err);
        err.println("Run ./" + name + " --help for its options.");
        return USAGE;
    }

    /** An unknown word where the launcher expects a command: says so and lists the commands. */
    private int unknown(String word, CommandLine launcher) {
        err.println("orchard: unknown " + (word.startsWith("-") ? "option" : "command") + " '" + word
                + "'; expected one of the commands below");
        err.print(launcher.getHelp().commandListHeading());
        err.print(launcher.getHelp().commandList());
        err.println();
        err.println("Run ./orchard --help for usage.");
        return USAGE;
    }

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
