package io.orchard.examples;

import io.orchard.protocol.value.Checks;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Converters of the launcher's option values for picocli ({@code @Option(converter = ...)}): each
 * error names the value and what was expected, and picocli puts the option's name in front of it,
 * as in {@code invalid value for option '--games': '0' is out of range (expected 1-1000 games)}.
 * A command with a range of its own subclasses {@link Whole} or {@link Decimal}.
 */
public final class OptionValues {

    private OptionValues() {
    }

    /** An integer from {@code min} to {@code max}. */
    public abstract static class Whole implements ITypeConverter<Integer> {

        private final int min;
        private final int max;
        private final String expected;

        /** @param expected what the value means, with its range, such as "1-1000 games" */
        protected Whole(int min, int max, String expected) {
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
    public abstract static class Decimal implements ITypeConverter<Double> {

        private final double min;
        private final double max;
        private final String expected;

        /** @param expected what the value means, with its range, such as "1-3600 seconds" */
        protected Decimal(double min, double max, String expected) {
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

    /** A seed: any whole number that fits in 64 bits. */
    public static final class Seed implements ITypeConverter<Long> {
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

    /** The port of a server to connect to. */
    public static final class Port extends Whole {
        /** A port from 1 to 65535. */
        public Port() {
            super(1, 65535, "a port 1-65535");
        }
    }

    /** An agent's name in the world: a letter, then up to 31 letters, digits, '_' or '-'. */
    public static final class AgentName implements ITypeConverter<String> {
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
