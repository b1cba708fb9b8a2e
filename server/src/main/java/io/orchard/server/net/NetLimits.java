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
 */
public record NetLimits(double messagesPerSecond, double burst, Duration idleTimeout, Duration slowConsumerGrace,
                        long maxPendingBytes) {

    /** 2,000 lines per second (burst 4,000), 120 s idle, 5 s to start reading, 64 MiB queued. */
    public static final NetLimits DEFAULT =
            new NetLimits(2_000, 4_000, Duration.ofSeconds(120), Duration.ofSeconds(5), 64L * 1024 * 1024);

    public NetLimits {
        if (!(messagesPerSecond > 0) || !(burst >= 1)) {
            throw new IllegalArgumentException("messagesPerSecond must be > 0 and burst >= 1, was "
                    + messagesPerSecond + " and " + burst);
        }
        if (idleTimeout.isNegative() || idleTimeout.isZero() || slowConsumerGrace.isNegative()) {
            throw new IllegalArgumentException("idleTimeout must be positive and slowConsumerGrace not negative, was "
                    + idleTimeout + " and " + slowConsumerGrace);
        }
        if (maxPendingBytes < 1024) {
            throw new IllegalArgumentException("maxPendingBytes must be at least 1024, was " + maxPendingBytes);
        }
    }
}
