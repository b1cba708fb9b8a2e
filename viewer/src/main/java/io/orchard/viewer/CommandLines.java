package io.orchard.viewer;

import io.orchard.cli.Decimal;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.ReplayState;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The converters of the viewer's options that {@code io.orchard.cli} does not have: each error names
 * the value and what was expected.
 */
final class CommandLines {

    private CommandLines() {
    }

    static final class Speed extends Decimal {
        Speed() {
            super(ReplayState.MIN_SPEED, ReplayState.MAX_SPEED, ReplayState.MIN_SPEED + "-" + (int) ReplayState.MAX_SPEED
                    + " simulated seconds per second");
        }
    }

    /** A simulated time: {@code --at}, {@code --until}. */
    static final class Time extends Decimal {
        Time() {
            super(0, 1e9, "a number of seconds, 0 or more");
        }
    }

    static final class Every extends Decimal {
        Every() {
            super(1e-3, 1e6, "0.001-1000000 seconds");
        }
    }

    static final class Timeout extends Decimal {
        Timeout() {
            super(1, 86_400, "1-86400 seconds");
        }
    }

    static final class Measure extends Decimal {
        Measure() {
            super(1, 3600, "1-3600 seconds");
        }
    }

    /** A frame's size in pixels. */
    record Size(int width, int height) {
    }

    /** {@code WIDTHxHEIGHT}, each 64 to 8192. */
    static final class SizeConverter implements ITypeConverter<Size> {
        @Override
        public Size convert(String text) {
            String[] parts = text.toLowerCase(Locale.ROOT).split("x");
            if (parts.length == 2) {
                try {
                    int width = Integer.parseInt(parts[0].strip());
                    int height = Integer.parseInt(parts[1].strip());
                    if (width >= 64 && height >= 64 && width <= 8192 && height <= 8192) {
                        return new Size(width, height);
                    }
                } catch (NumberFormatException e) {
                    // the message below says what was expected
                }
            }
            throw new TypeConversionException("'" + text + "' is not a size (expected WIDTHxHEIGHT in pixels, each 64 "
                    + "to 8192, such as 1280x720)");
        }
    }

    /** {@code X,Y,Z}: three finite numbers. */
    static final class Point implements ITypeConverter<Vec3> {
        @Override
        public Vec3 convert(String text) {
            String[] parts = text.split(",");
            if (parts.length == 3) {
                try {
                    double x = Double.parseDouble(parts[0].strip());
                    double y = Double.parseDouble(parts[1].strip());
                    double z = Double.parseDouble(parts[2].strip());
                    if (Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) {
                        return new Vec3(x, y, z);
                    }
                } catch (NumberFormatException e) {
                    // the message below says what was expected
                }
            }
            throw new TypeConversionException("'" + text + "' is not a point (expected three numbers X,Y,Z such as "
                    + "10,25,40)");
        }
    }

    /** An agent's name: a letter, then up to 31 letters, digits, _ or -. */
    static final class AgentName implements ITypeConverter<String> {
        @Override
        public String convert(String text) {
            if (!text.matches("[A-Za-z][A-Za-z0-9_-]{0,31}")) {
                throw new TypeConversionException("'" + text + "' is not an agent's name (expected a letter, then up "
                        + "to 31 letters, digits, _ or -)");
            }
            return text;
        }
    }

    /** {@code on} or {@code off}, in any case, read as lower case; the two words for the help and completion. */
    static final class OnOff implements ITypeConverter<String>, Iterable<String> {
        @Override
        public String convert(String text) {
            String word = text.strip().toLowerCase(Locale.ROOT);
            if (!word.equals("on") && !word.equals("off")) {
                throw new TypeConversionException("'" + text + "' is neither on nor off (expected on or off)");
            }
            return word;
        }

        @Override
        public Iterator<String> iterator() {
            return List.of("on", "off").iterator();
        }
    }
}
