package io.orchard.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** A seed: any whole number that fits in 64 bits. */
public final class Seed implements ITypeConverter<Long> {

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
