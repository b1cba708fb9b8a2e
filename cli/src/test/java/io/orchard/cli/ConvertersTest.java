package io.orchard.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import picocli.CommandLine.TypeConversionException;

class ConvertersTest {

    static final class Games extends Whole {
        Games() {
            super(1, 1000, "1-1000 games");
        }
    }

    static final class Seconds extends Decimal {
        Seconds() {
            super(1, 3600, "1-3600 seconds");
        }
    }

    @Test
    void valuesInRangeAreReadWithSpaceAroundThem() {
        assertThat(new Games().convert(" 1000 ")).isEqualTo(1000);
        assertThat(new Seconds().convert("1")).isEqualTo(1.0);
        assertThat(new Seconds().convert("3600")).isEqualTo(3600.0);
        assertThat(new Seed().convert("-9223372036854775808")).isEqualTo(Long.MIN_VALUE);
        assertThat(new Port().convert("65535")).isEqualTo(65535);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        whole not integer  | games   | 1.5                  | '1.5' is not an integer (expected 1-1000 games)
        whole below        | games   | 0                    | '0' is out of range (expected 1-1000 games)
        whole above        | games   | 1001                 | '1001' is out of range (expected 1-1000 games)
        decimal not number | seconds | soon                 | 'soon' is not a number (expected 1-3600 seconds)
        decimal above      | seconds | 3600.5               | '3600.5' is out of range (expected 1-3600 seconds)
        decimal NaN        | seconds | NaN                  | 'NaN' is out of range (expected 1-3600 seconds)
        seed too large     | seed    | 9223372036854775808  | '9223372036854775808' is not an integer (expected a seed: a whole number from -2^63 to 2^63-1)
        port zero          | port    | 0                    | '0' is out of range (expected a port 1-65535)
        port not integer   | port    | seven                | 'seven' is not an integer (expected a port 1-65535)
        """)
    void badValuesAreNamedWithWhatWasExpected(String name, String converter, String text, String message) {
        assertThatThrownBy(() -> {
            switch (converter) {
                case "games" -> new Games().convert(text);
                case "seconds" -> new Seconds().convert(text);
                case "seed" -> new Seed().convert(text);
                default -> new Port().convert(text);
            }
        }).isInstanceOf(TypeConversionException.class).hasMessage(message);
    }
}
