package io.orchard.server;

import java.time.Duration;

/**
 * The checks of the options a {@link WorldServer} and a cluster's node both take, each with the one
 * wording its refusal has wherever the option is given: the two builders share them so that an option
 * is not checked differently, or named differently, by one of them. Each returns the value it passed.
 */
public final class OptionChecks {

    private OptionChecks() {}

    /**
     * A port to listen on, 0 for any free one.
     *
     * @param what the port's name in the refusal, "port" or "HTTP port" for example
     */
    public static int port(int port, String what) {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException(what + " must be 0 to 65535, was " + port);
        }
        return port;
    }

    /** Ticks per simulated second, 1 to 1000. */
    public static int tickRate(int tickRate) {
        if (tickRate < 1 || tickRate > 1000) {
            throw new IllegalArgumentException("tick rate must be 1 to 1000 ticks per second, was " + tickRate);
        }
        return tickRate;
    }

    /** A game's length, a positive and finite number of simulated seconds. */
    public static double timeLimit(double seconds) {
        if (!(seconds > 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("time limit must be a positive number of seconds, was " + seconds);
        }
        return seconds;
    }

    /** How many agents a game waits for before it starts, 0 or more. */
    public static int waitFor(int agents) {
        if (agents < 0) {
            throw new IllegalArgumentException("waitFor must not be negative, was " + agents);
        }
        return agents;
    }

    /** How long a lockstep tick waits for agents' turns, positive. */
    public static Duration lockstepDeadline(Duration deadline) {
        if (deadline == null || deadline.isNegative() || deadline.isZero()) {
            throw new IllegalArgumentException("lockstep deadline must be positive, was " + deadline);
        }
        return deadline;
    }

    /** How long a dropped agent's name stays its controller's, zero or more. */
    public static Duration nameReservation(Duration time) {
        if (time == null || time.isNegative()) {
            throw new IllegalArgumentException("name reservation must be zero or more, was " + time);
        }
        return time;
    }

    /** How often a checkpoint is written by the clock: positive, or null for never. */
    public static Duration checkpointInterval(Duration every) {
        if (every != null && (every.isNegative() || every.isZero())) {
            throw new IllegalArgumentException("checkpoint interval must be positive, was " + every);
        }
        return every;
    }

    /**
     * The secret every client presents in its hello, or null for none; an empty one would look set
     * and admit everyone. It must differ from {@code operatorToken} (null: not set yet).
     */
    public static String token(String token, String operatorToken) {
        if (token != null && token.isEmpty()) {
            throw new IllegalArgumentException("token must not be empty");
        }
        differentTokens(token, operatorToken);
        return token;
    }

    /**
     * The secret that lets a client control the game, or null for none. It must differ from
     * {@code token} (null: not set), which every client holds.
     */
    public static String operatorToken(String operatorToken, String token) {
        if (operatorToken != null && operatorToken.isEmpty()) {
            throw new IllegalArgumentException("operator token must not be empty");
        }
        differentTokens(token, operatorToken);
        return operatorToken;
    }

    private static void differentTokens(String token, String operatorToken) {
        if (token != null && token.equals(operatorToken)) {
            throw new IllegalArgumentException("the operator token must differ from the token: every client"
                    + " holds the token, and would control the game");
        }
    }
}
