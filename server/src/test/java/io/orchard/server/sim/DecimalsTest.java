package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Two decimal places exactly as the formatter writes them, or recordings of rejected moves would change. */
class DecimalsTest {

    @ParameterizedTest
    @ValueSource(doubles = {0.0, -0.0, 0.005, -0.005, 0.015, 1.005, 2.675, 0.125, -0.125, 9.995, 99.995, -1e-9,
        1e-3, 4.999999999999999e-3, 12.5, -40.25, 123456789.125, 1e300, -1e300, Double.MIN_VALUE, Double.MAX_VALUE,
        Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY})
    void aNumberIsWrittenAsTheFormatterWritesIt(double value) {
        assertThat(Decimals.twoPlaces(value)).isEqualTo(String.format(Locale.ROOT, "%.2f", value));
    }

    @Test
    void numbersOfEveryKindAreWrittenAsTheFormatterWritesThem() {
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 200_000; i++) {
            double value = switch (i % 5) {
                case 0 -> random.nextDouble(-1000, 1000);
                case 1 -> Math.round(random.nextDouble(-1e6, 1e6)) / 200.0 + (random.nextBoolean() ? 0.005 : -0.005);
                case 2 -> Double.longBitsToDouble(random.nextLong());
                case 3 -> random.nextDouble(-1, 1) * Math.pow(10, random.nextInt(-10, 20));
                default -> Math.round(random.nextDouble(-1e7, 1e7)) / 1000.0 + 0.0005;
            };
            assertThat(Decimals.twoPlaces(value)).as("%s", value).isEqualTo(String.format(Locale.ROOT, "%.2f", value));
        }
    }
}
