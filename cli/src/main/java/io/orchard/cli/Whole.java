package io.orchard.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * An integer from {@code min} to {@code max}, for an option whose converter subclasses this with
 * its range, as in {@code '0' is out of range (expected 1-1000 games)}.
 */
public abstract class Whole implements ITypeConverter<Integer> {

    private final int min;
    private final int max;
    private final String expected;

    /**
     * Values from {@code min} to {@code max}, both included.
     *
     * @param expected what the value means, with its range, such as "1-1000 games"
     */
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
