package io.orchard.server;

import io.orchard.protocol.value.ClockMode;
import java.io.PrintStream;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * What the server's command line needs from picocli besides its annotations: converters whose
 * errors name the value and what was expected, and a run on its own that prints a wrong command
 * line as {@code orchard server: <what is wrong>} with exit status 2, and a failure with status 1.
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

    /** What is wrong with a command line, as a phrase to follow "orchard server: ". */
    static String describe(ParameterException e) {
        if (e instanceof UnmatchedArgumentException unmatched && !unmatched.isUnknownOption()) {
            List<String> args = unmatched.getUnmatched();
            return "unexpected argument" + (args.size() == 1 ? " " : "s ")
                    + String.join(", ", args.stream().map(arg -> "'" + arg + "'").toList()) + " (options start with --)";
        }
        String message = e.getMessage();
        return message.isEmpty() ? message : Character.toLowerCase(message.charAt(0)) + message.substring(1);
    }

    /** An integer from {@code min} to {@code max}. */
    abstract static class Whole implements ITypeConverter<Integer> {

        private final int min;
        private final int max;
        private final String expected;

        Whole(int min, int max, String expected) {
            this.min = min;
            this.max = max;
            this.expected = expected;
        }

        @Override
        public Integer convert(String text) {
            int value;
            try {
                value = Integer.parseInt(text.strip());
            } catch (NumberFormatException e) {
                throw new TypeConversionException("'" + text + "' is not an integer (expected " + expected + ")");
            }
            if (value < min || value > max) {
                throw new TypeConversionException("'" + text + "' is out of range (expected " + expected + ")");
            }
            return value;
        }
    }

    /** A number from {@code min} to {@code max}. */
    abstract static class Decimal implements ITypeConverter<Double> {

        private final double min;
        private final double max;
        private final String expected;

        Decimal(double min, double max, String expected) {
            this.min = min;
            this.max = max;
            this.expected = expected;
        }

        @Override
        public Double convert(String text) {
            double value;
            try {
                value = Double.parseDouble(text.strip());
            } catch (NumberFormatException e) {
                throw new TypeConversionException("'" + text + "' is not a number (expected " + expected + ")");
            }
            if (!(value >= min && value <= max)) {
                throw new TypeConversionException("'" + text + "' is out of range (expected " + expected + ")");
            }
            return value;
        }
    }

    static final class Port extends Whole {
        Port() {
            super(0, 65535, "a port 0-65535");
        }
    }

    static final class TickRate extends Whole {
        TickRate() {
            super(1, 1000, "1-1000 ticks per simulated second");
        }
    }

    static final class WaitFor extends Whole {
        WaitFor() {
            super(0, 10_000, "0-10000 agents");
        }
    }

    static final class TimeLimit extends Decimal {
        TimeLimit() {
            super(0.001, 1e7, "0.001-10000000 simulated seconds");
        }
    }

    static final class CheckpointEvery extends Decimal {
        CheckpointEvery() {
            super(0, 1e7, "0-10000000 seconds; 0 for never");
        }
    }

    /** A seed: any whole number that fits in 64 bits. */
    static final class Seed implements ITypeConverter<Long> {
        @Override
        public Long convert(String text) {
            try {
                return Long.parseLong(text.strip());
            } catch (NumberFormatException e) {
                throw new TypeConversionException("'" + text + "' is not an integer (expected a seed: a whole number "
                        + "from -2^63 to 2^63-1)");
            }
        }
    }

    /** A clock mode by its name in any case: realtime or lockstep. */
    static final class Clock implements ITypeConverter<ClockMode>, Iterable<String> {
        @Override
        public ClockMode convert(String text) {
            for (ClockMode mode : ClockMode.values()) {
                if (mode.wireName().equalsIgnoreCase(text.strip())) {
                    return mode;
                }
            }
            throw new TypeConversionException("'" + text + "' is not a clock (expected one of " + String.join(", ", this)
                    + ")");
        }

        /** The names, lower case, for the help and for shell completion. */
        @Override
        public Iterator<String> iterator() {
            return Arrays.stream(ClockMode.values()).map(ClockMode::wireName).iterator();
        }
    }
}
