package io.orchard.server;

import io.orchard.cli.Decimal;
import io.orchard.cli.Whole;
import io.orchard.protocol.value.ClockMode;
import java.util.Arrays;
import java.util.Iterator;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The converters of the server's options that {@code io.orchard.cli} does not have: each error names
 * the value and what was expected.
 */
final class CommandLines {

    private CommandLines() {
    }

    /** A port to listen on, 0 for any free one. */
    static final class Port extends Whole {
        Port() {
            super(0, 65535, "a port 0-65535");
        }
    }

    static final class TickRate extends Whole {
        TickRate() {
            super(1, 1000, "1-1000 ticks per simulated second");
        }
    }

    static final class WaitFor extends Whole {
        WaitFor() {
            super(0, 10_000, "0-10000 agents");
        }
    }

    static final class TimeLimit extends Decimal {
        TimeLimit() {
            super(0.001, 1e7, "0.001-10000000 simulated seconds");
        }
    }

    static final class TurnDeadline extends Decimal {
        TurnDeadline() {
            super(0.001, 3600, "0.001-3600 seconds");
        }
    }

    static final class CheckpointEvery extends Decimal {
        CheckpointEvery() {
            super(0, 1e7, "0-10000000 seconds; 0 for never");
        }
    }

    static final class NameReservation extends Decimal {
        NameReservation() {
            super(0, 1e7, "0-10000000 seconds; 0 frees a dropped agent's name at once");
        }
    }

    /** A clock mode by its name in any case: realtime or lockstep. */
    static final class Clock implements ITypeConverter<ClockMode>, Iterable<String> {
        @Override
        public ClockMode convert(String text) {
            for (ClockMode mode : ClockMode.values()) {
                if (mode.wireName().equalsIgnoreCase(text.strip())) {
                    return mode;
                }
            }
            throw new TypeConversionException("'" + text + "' is not a clock (expected one of " + String.join(", ", this)
                    + ")");
        }

        /** The names, lower case, for the help and for shell completion. */
        @Override
        public Iterator<String> iterator() {
            return Arrays.stream(ClockMode.values()).map(ClockMode::wireName).iterator();
        }
    }
}
