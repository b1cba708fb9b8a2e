package io.orchard.server.sim;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Locale;

/**
 * Numbers in the texts of replies, written as {@code String.format(Locale.ROOT, "%.2f", value)}
 * writes them, character for character (so that recordings stay the same), without the formatter's
 * parsing and locale lookups: a late move's rejection names four numbers, and a realtime client's
 * moves are often late.
 */
final class Decimals {

    private Decimals() {}

    /**
     * Two decimal places, rounded half up from the digits {@link Double#toString} gives, as the
     * formatter rounds; a minus sign for anything below zero, −0.0 included.
     */
    static String twoPlaces(double value) {
        if (!Double.isFinite(value)) {
            return String.format(Locale.ROOT, "%.2f", value);
        }
        String digits = new BigDecimal(Double.toString(Math.abs(value))).setScale(2, RoundingMode.HALF_UP)
                .toPlainString();
        return Double.compare(value, 0.0) < 0 ? "-" + digits : digits;
    }
}
