package io.orchard.server.net;

import java.time.Duration;

/**
 * The limits the server's connections live under, one by one and all together. The defaults suit
 * a classroom: generous for an honest client, short enough that a broken or hostile one is cut off
 * before it costs the others, and small enough together that no mix of clients can make the
 * server's memory grow without bound (docs/security.md adds them up).
 *
 * @param messagesPerSecond     sustained lines a client may send per second
 * @param burst                 lines a client may send at once before the rate applies
 * @param idleTimeout           how long an agent's connection may send nothing before it is closed
 *                              (viewers only listen, and are exempt once welcomed)
 * @param slowConsumerGrace     how far behind a client may fall: the longest the oldest of the
 *                              output waiting for it may wait before it is cut off
 * @param maxPendingBytes       bytes that may wait for one client (models shared with others not
 *                              counted) before it is cut off
 * @param lineDeadline          how long a client may take to finish a line once its first byte came
 * @param maxConnections        connections the server takes at once; the next is refused
 * @param helloDeadline         how long a new connection may take to send its {@code Hello}
 * @param maxWaitingForHello    connections that may wait for their {@code Hello} at once; a new
 *                              one beyond closes the one that has waited longest
 * @param maxPendingBytesInAll  bytes that may wait for all clients together; beyond, the client
 *                              with the most waiting is cut off
 * @param modelBytesPerConnection decoded bytes of the different models one connection may register
 *                              over its life
 * @param modelBytesInAll       decoded bytes of the different models the server holds at once
 * @param largeLinesAtOnce      lines longer than an ordinary message (registrations with a model)
 *                              the server receives at once; other connections sending one wait
 */
public record NetLimits(double messagesPerSecond, double burst, Duration idleTimeout, Duration slowConsumerGrace,
                        long maxPendingBytes, Duration lineDeadline, int maxConnections, Duration helloDeadline,
                        int maxWaitingForHello, long maxPendingBytesInAll, long modelBytesPerConnection,
                        long modelBytesInAll, int largeLinesAtOnce) {

    /** How long a line may take by default: 30 s, time enough to send a model of 8 MiB at 2 Mbit/s. */
    public static final Duration DEFAULT_LINE_DEADLINE = Duration.ofSeconds(30);

    /** Connections taken at once by default. */
    public static final int DEFAULT_MAX_CONNECTIONS = 1024;

    /** How long a new connection has to say {@code Hello} by default. */
    public static final Duration DEFAULT_HELLO_DEADLINE = Duration.ofSeconds(5);

    /** Connections that may wait for their {@code Hello} at once by default. */
    public static final int DEFAULT_MAX_WAITING_FOR_HELLO = 256;

    /** Bytes waiting for all clients together by default: 256 MiB. */
    public static final long DEFAULT_MAX_PENDING_BYTES_IN_ALL = 256L << 20;

    /** Model bytes one connection may register by default: 8 MiB, two models of the largest size. */
    public static final long DEFAULT_MODEL_BYTES_PER_CONNECTION = 8L << 20;

    /** Model bytes the server holds at once by default: 32 MiB, eight models of the largest size. */
    public static final long DEFAULT_MODEL_BYTES_IN_ALL = 32L << 20;

    /** Large lines received at once by default. */
    public static final int DEFAULT_LARGE_LINES_AT_ONCE = 16;

    /**
     * 2,000 lines per second (burst 4,000), 120 s idle, 10 s behind at most, 16 MiB waiting for one
     * client and 256 MiB for all, 30 s to finish a line, 1,024 connections, 5 s to say {@code Hello}
     * and 256 connections waiting to, 8 MiB of models per connection and 32 MiB in all, 16 large lines
     * at once.
     */
    public static final NetLimits DEFAULT = new NetLimits(2_000, 4_000, Duration.ofSeconds(120),
            Duration.ofSeconds(10), 16L << 20);

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
        if (maxPendingBytes < 1024 || maxPendingBytesInAll < maxPendingBytes) {
            throw new IllegalArgumentException("maxPendingBytes must be at least 1024 and maxPendingBytesInAll at least"
                    + " as much, was " + maxPendingBytes + " and " + maxPendingBytesInAll);
        }
        positive(lineDeadline, "lineDeadline");
        positive(helloDeadline, "helloDeadline");
        if (maxConnections < 1 || maxWaitingForHello < 1 || largeLinesAtOnce < 1) {
            throw new IllegalArgumentException("maxConnections, maxWaitingForHello and largeLinesAtOnce must be at"
                    + " least 1, was " + maxConnections + ", " + maxWaitingForHello + " and " + largeLinesAtOnce);
        }
        if (modelBytesPerConnection < 0 || modelBytesInAll < 0) {
            throw new IllegalArgumentException("modelBytesPerConnection and modelBytesInAll must not be negative, was "
                    + modelBytesPerConnection + " and " + modelBytesInAll);
        }
    }

    private static void positive(Duration duration, String name) {
        if (duration == null || duration.isNegative() || duration.isZero()) {
            throw new IllegalArgumentException(name + " must be positive, was " + duration);
        }
    }

    /** Limits with the given rates and per-client bounds, and the defaults for the rest. */
    public NetLimits(double messagesPerSecond, double burst, Duration idleTimeout, Duration slowConsumerGrace,
                     long maxPendingBytes) {
        this(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, DEFAULT_LINE_DEADLINE,
                DEFAULT_MAX_CONNECTIONS, DEFAULT_HELLO_DEADLINE, DEFAULT_MAX_WAITING_FOR_HELLO,
                Math.max(maxPendingBytes, DEFAULT_MAX_PENDING_BYTES_IN_ALL), DEFAULT_MODEL_BYTES_PER_CONNECTION,
                DEFAULT_MODEL_BYTES_IN_ALL, DEFAULT_LARGE_LINES_AT_ONCE);
    }

    /** These limits with another line deadline. */
    public NetLimits withLineDeadline(Duration deadline) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, deadline,
                maxConnections, helloDeadline, maxWaitingForHello, maxPendingBytesInAll, modelBytesPerConnection,
                modelBytesInAll, largeLinesAtOnce);
    }

    /** These limits with another connection count. */
    public NetLimits withMaxConnections(int connections) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, lineDeadline,
                connections, helloDeadline, maxWaitingForHello, maxPendingBytesInAll, modelBytesPerConnection,
                modelBytesInAll, largeLinesAtOnce);
    }

    /** These limits with another deadline for the {@code Hello} and number of connections waiting to send it. */
    public NetLimits withHello(Duration deadline, int waiting) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, lineDeadline,
                maxConnections, deadline, waiting, maxPendingBytesInAll, modelBytesPerConnection, modelBytesInAll,
                largeLinesAtOnce);
    }

    /** These limits with another time and byte count a client may fall behind by, and bytes waiting for all. */
    public NetLimits withSlowConsumers(Duration grace, long pendingBytes, long pendingBytesInAll) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, grace, pendingBytes, lineDeadline, maxConnections,
                helloDeadline, maxWaitingForHello, pendingBytesInAll, modelBytesPerConnection, modelBytesInAll,
                largeLinesAtOnce);
    }

    /** These limits with other caps on models, per connection and in all. */
    public NetLimits withModelBytes(long perConnection, long inAll) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, lineDeadline,
                maxConnections, helloDeadline, maxWaitingForHello, maxPendingBytesInAll, perConnection, inAll,
                largeLinesAtOnce);
    }

    /** These limits with another number of large lines received at once. */
    public NetLimits withLargeLinesAtOnce(int lines) {
        return new NetLimits(messagesPerSecond, burst, idleTimeout, slowConsumerGrace, maxPendingBytes, lineDeadline,
                maxConnections, helloDeadline, maxWaitingForHello, maxPendingBytesInAll, modelBytesPerConnection,
                modelBytesInAll, lines);
    }
}
