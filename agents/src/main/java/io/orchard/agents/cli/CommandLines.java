package io.orchard.agents.cli;

import io.orchard.agents.zoo.Species;
import io.orchard.protocol.value.Checks;
import java.util.Arrays;
import java.util.Iterator;
import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The converters of the agents' options that {@code io.orchard.cli} does not have: each error names
 * the value and what was expected.
 */
final class CommandLines {

    private CommandLines() {
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
