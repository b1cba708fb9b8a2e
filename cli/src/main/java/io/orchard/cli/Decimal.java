package io.orchard.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * A number from {@code min} to {@code max}, for an option whose converter subclasses this with its
 * range, as in {@code 'x' is not a number (expected 1-3600 seconds)}.
 */
public abstract class Decimal implements ITypeConverter<Double> {

    private final double min;
    private final double max;
    private final String expected;

    /**
     * Values from {@code min} to {@code max}, both included.
     *
     * @param expected what the value means, with its range, such as "1-3600 seconds"
     */
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
        if (!(value >= min && value <= max)) { // also refuses NaN
            throw new TypeConversionException("'" + text + "' is out of range (expected " + expected + ")");
        }
        return value;
    }
}
