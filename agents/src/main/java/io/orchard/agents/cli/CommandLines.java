package io.orchard.agents.cli;

import io.orchard.agents.zoo.Species;
import io.orchard.protocol.value.Checks;
import java.io.PrintStream;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * What the agents' command lines need from picocli besides their annotations: converters whose
 * errors name the value and what was expected, and a run on its own that prints a wrong command
 * line as {@code orchard agent: <what is wrong>} with exit status 2, and a failure with status 1.
 */
final class CommandLines {

    static final int FAILED = 1;
    static final int USAGE = 2;

    private CommandLines() {
    }

    /** Runs {@code line} on {@code args}, printing errors to {@code err}; returns the exit status. */
    static int execute(CommandLine line, List<String> args, PrintStream err) {
        line.setParameterExceptionHandler((e, given) -> {
            String name = e.getCommandLine().getCommandSpec().qualifiedName();
            err.println(name + ": " + describe(e));
            UnmatchedArgumentException.printSuggestions(e, err);
            err.println("Run ./" + name + " --help for its options.");
            return USAGE;
        });
        line.setExecutionExceptionHandler((e, failed, parsed) -> {
            err.println(failed.getCommandSpec().qualifiedName() + ": " + (e.getMessage() == null ? e : e.getMessage()));
            if (e instanceof RuntimeException) {
                e.printStackTrace(err); // a defect rather than a condition the message explains
            }
            return FAILED;
        });
        return line.execute(args.toArray(String[]::new));
    }

    /** What is wrong with a command line, as a phrase to follow "orchard agent: ". */
    static String describe(ParameterException e) {
        if (e instanceof UnmatchedArgumentException unmatched && !unmatched.isUnknownOption()) {
            List<String> args = unmatched.getUnmatched();
            return "unexpected argument" + (args.size() == 1 ? " " : "s ")
                    + String.join(", ", args.stream().map(arg -> "'" + arg + "'").toList()) + " (options start with --)";
        }
        String message = e.getMessage();
        return message.isEmpty() ? message : Character.toLowerCase(message.charAt(0)) + message.substring(1);
    }

    /** The port of a server to connect to. */
    static final class Port implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            int port;
            try {
                port = Integer.parseInt(text.strip());
            } catch (NumberFormatException e) {
                throw new TypeConversionException("'" + text + "' is not an integer (expected a port 1-65535)");
            }
            if (port < 1 || port > 65535) {
                throw new TypeConversionException("'" + text + "' is out of range (expected a port 1-65535)");
            }
            return port;
        }
    }

    /** A species of the zoo by its name in any case; its names, lower case, for the help and completion. */
    static final class Type implements ITypeConverter<Species>, Iterable<String> {
        @Override
        public Species convert(String text) {
            try {
                return Species.named(text);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }

        @Override
        public Iterator<String> iterator() {
            return Arrays.stream(Species.values()).map(s -> s.name().toLowerCase(Locale.ROOT)).iterator();
        }
    }

    /** An agent's name in the world. */
    static final class Name implements ITypeConverter<String> {
        @Override
        public String convert(String text) {
            try {
                return Checks.name(text, "an agent's name");
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }
}
