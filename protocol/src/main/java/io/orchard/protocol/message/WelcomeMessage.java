package io.orchard.protocol.message;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GamePhase;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Role;

/**
 * The server's answer to {@link HelloMessage}: the connection is open and this is the world.
 *
 * @param seq the hello's sequence number
 * @param protocolVersion the protocol version the server speaks
 * @param serverVersion the server's software version
 * @param role the role the client was admitted as
 * @param bounds the rectangle agents may walk on
 * @param tickRate simulation ticks per simulated second
 * @param clock realtime or lockstep
 * @param tick the current tick
 * @param timeLimit the game's length in simulated seconds (version 2), so that a client that joins
 *                  a game under way knows it without having seen {@code GameStarted}
 * @param phase where the game is (version 2): waiting, running, paused or over
 */
public record WelcomeMessage(long seq,
                             int protocolVersion,
                             String serverVersion,
                             Role role,
                             Bounds bounds,
                             int tickRate,
                             ClockMode clock,
                             long tick,
                             @Nullable Double timeLimit,
                             @Nullable GamePhase phase) implements ServerMessage, Reply {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public WelcomeMessage {
        Checks.nonNegative(seq, "seq");
        if (protocolVersion <= 0) {
            throw new IllegalArgumentException("protocolVersion must be greater than 0, was " + protocolVersion);
        }
        Checks.text(serverVersion, "serverVersion");
        Checks.present(role, "role");
        Checks.present(bounds, "bounds");
        if (tickRate <= 0) {
            throw new IllegalArgumentException("tickRate must be greater than 0, was " + tickRate);
        }
        Checks.present(clock, "clock");
        Checks.nonNegative(tick, "tick");
        if (timeLimit != null) {
            Checks.nonNegative(timeLimit, "timeLimit");
        }
    }

    /** A welcome without the game's time limit and phase, as version 1 clients get it. */
    public WelcomeMessage(long seq, int protocolVersion, String serverVersion, Role role, Bounds bounds, int tickRate,
                          ClockMode clock, long tick) {
        this(seq, protocolVersion, serverVersion, role, bounds, tickRate, clock, tick, null, null);
    }

    /** The same welcome as a client of {@code version} gets it: without the fields of version 2 for version 1. */
    public WelcomeMessage forVersion(int version) {
        return version >= 2 || (timeLimit == null && phase == null) ? this
                : new WelcomeMessage(seq, protocolVersion, serverVersion, role, bounds, tickRate, clock, tick);
    }
}
