package io.orchard.examples;

import io.orchard.protocol.value.Checks;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Converters of the launcher's option values for picocli ({@code @Option(converter = ...)}) that
 * {@code io.orchard.cli} does not have: each error names the value and what was expected, and
 * picocli puts the option's name in front of it. A command with a range of its own subclasses
 * {@link io.orchard.cli.Whole} or {@link io.orchard.cli.Decimal}.
 */
public final class OptionValues {

    private OptionValues() {
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
