package io.orchard.examples;

import io.orchard.cli.CommandLineErrors;
import java.io.PrintStream;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.IParameterExceptionHandler;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * How the launcher answers what goes wrong: as every command does ({@link CommandLineErrors}), but
 * an unknown word where the launcher expects a command gets the list of the commands.
 */
final class LauncherErrors implements IParameterExceptionHandler, IExecutionExceptionHandler {

    private final PrintStream err;
    private final CommandLineErrors commands;

    LauncherErrors(PrintStream err) {
        this.err = err;
        this.commands = new CommandLineErrors(err);
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
        return commands.handleParseException(e, args);
    }

    /** An unknown word where the launcher expects a command: says so and lists the commands. */
    private int unknown(String word, CommandLine launcher) {
        err.println("orchard: unknown " + (word.startsWith("-") ? "option" : "command") + " '" + word
                + "'; expected one of the commands below");
        err.print(launcher.getHelp().commandListHeading());
        err.print(launcher.getHelp().commandList());
        err.println();
        err.println("Run ./orchard --help for usage.");
        return CommandLineErrors.USAGE;
    }

    @Override
    public int handleExecutionException(Exception e, CommandLine failed, ParseResult parsed) {
        return commands.handleExecutionException(e, failed, parsed);
    }
}
