package io.orchard.server.net;

import java.time.Duration;

/**
 * The limits one connection lives under. The defaults suit a classroom: generous for an honest
 * agent, short enough that a broken or hostile client is cut off before it costs the others.
 *
 * @param messagesPerSecond sustained lines a client may send per second
 * @param burst             lines a client may send at once before the rate applies
 * @param idleTimeout       how long a connection may send nothing before it is closed
 * @param slowConsumerGrace how long a client may leave its messages unread before it is cut off
 * @param maxPendingBytes   bytes queued for a client beyond which it is cut off at once
 * @param lineDeadline      how long a client may take to finish a line once its first byte came
 * @param maxConnections    connections the server takes at once; the next is refused
 */
public record NetLimits(double messagesPerSecond, double burst, Duration idleTimeout, Duration slowConsumerGrace,
                        long maxPendingBytes, Duration lineDeadline, int maxConnections) {

    /** How long a line may take by default: 30 s, time enough to send a model of 8 MiB at 2 Mbit/s. */
    public static final Duration DEFAULT_LINE_DEADLINE = Duration.ofSeconds(30);

    /** Connections taken at once by default. */
    public static final int DEFAULT_MAX_CONNECTIONS = 1024;

    /**
     * 2,000 lines per second (burst 4,000), 120 s idle, 5 s to start reading, 64 MiB queued, 30 s to
     * finish a line, 1,024 connections.
     */
    public static final NetLimits DEFAULT = new NetLimits(2_000, 4_000, Duration.ofSeconds(120), Duration.ofSeconds(5),
            64L * 1024 * 1024);

    /** Checks the components; a bad value is refused with an exception that names it. */
    public NetLimits {
        if (!(messagesPerSecond > 0) || !(burst >= 1)) {
            throw new IllegalArgumentException("messagesPerSecond must be > 0 and burst >= 1, was "
                    + messagesPerSecond + " and " + burst);
        }
        if (idleTimeout == null || idleTimeout.isNegative() || idleTimeout.isZero() || slowConsumerGrace == null
                || slowConsumerGrace.isNegative()) {
            throw new IllegalArgumentException("idleTimeout must be positive and slowConsumerGrace not negative, was "
                    + idleTimeout + " and " + slowConsumerGrace);
        }
        if (maxPendingBytes < 1024) {
            throw new IllegalArgumentException("maxPendingBytes must be at least 1024, was " + maxPendingBytes);
        }
        if (lineDeadline == null || lineDeadline.isNegative() || lineDeadline.isZero()) {
            throw new IllegalArgumentException("lineDeadline must be positive, was " + lineDeadline);
        }
        if (maxConnections < 1) {
            throw new IllegalArgumentException("maxConnections must be at least 1, was " + maxConnections);
        }
    }

    /** Limits with the default line deadline and connection count. */
    public NetLimits(double messagesPerSecond, double burst, Duration idleTimeout, Duration slowConsumerGrace,
                     long maxPendingBytes) {
        this(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, DEFAULT_LINE_DEADLINE,
                DEFAULT_MAX_CONNECTIONS);
    }

    /** These limits with another line deadline. */
    public NetLimits withLineDeadline(Duration deadline) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, deadline,
                maxConnections);
    }

    /** These limits with another connection count. */
    public NetLimits withMaxConnections(int connections) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, lineDeadline,
                connections);
    }
}
