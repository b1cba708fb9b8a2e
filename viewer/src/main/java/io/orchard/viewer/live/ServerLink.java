package io.orchard.viewer.live;

import io.orchard.protocol.client.HandshakeRefusedException;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Role;
import java.io.IOException;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.LongFunction;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A viewer's connection to a live server that never ends in silence. When it ends it says why —
 * the error the server closed it with, the end of the stream, an I/O error, a refused handshake —
 * in the log and to its {@link Listener}; then, with a {@link Backoff}, it connects again after a
 * growing wait, for as long as it is open, so that a server that is restarted is watched again.
 * A handshake refused for good (a wrong token, another protocol version) is not tried again.
 *
 * <p>Its own daemon thread connects and waits; the listener hears a connection's messages on that
 * connection's reader thread, in order, each connection's {@link Listener#connected()} before its
 * first message.
 */
public final class ServerLink implements AutoCloseable {

    /** Hears what happens on the link. */
    public interface Listener {

        /** A connection is open; its messages follow, a viewer's snapshot first. */
        default void connected() {}

        /** The server's welcome on the connection that opened (it may come after the first messages). */
        default void welcomed(WelcomeMessage welcome) {}

        /** A message from the server. */
        void received(ServerMessage message);

        /**
         * The connection ended, or could not be made.
         *
         * @param reason  why, in words that name the server and the cause
         * @param retryIn how long until the next attempt, or null when there will be none
         */
        void ended(String reason, Duration retryIn);
    }

    private static final Logger LOG = LoggerFactory.getLogger(ServerLink.class);

    private final String host;
    private final int port;
    private final String token;
    private final String operatorToken;
    private final Backoff backoff;
    private final Listener listener;
    private final Thread thread;
    private volatile ProtocolConnection connection;
    private volatile boolean closed;

    /**
     * A link to the server at {@code host}:{@code port}, not yet started.
     *
     * @param token         the server's token, or null when it needs none
     * @param operatorToken the server's operator token, or null to watch as an ordinary viewer
     * @param backoff       the waits before connecting again, or null never to connect again
     */
    public ServerLink(String host, int port, String token, String operatorToken, Backoff backoff,
                      Listener listener) {
        this.host = host;
        this.port = port;
        this.token = token;
        this.operatorToken = operatorToken;
        this.backoff = backoff;
        this.listener = listener;
        this.thread = new Thread(this::run, "orchard-viewer-link");
        this.thread.setDaemon(true);
    }

    /** Connects, on the link's own thread. */
    public void start() {
        thread.start();
    }

    /** Where the link connects: host:port. */
    public String server() {
        return host + ":" + port;
    }

    /** Whether a connection is open now. */
    public boolean isConnected() {
        ProtocolConnection open = connection;
        return open != null && open.isOpen();
    }

    /**
     * Sends a message and returns the server's reply to it; fails at once when no connection is
     * open.
     */
    public CompletableFuture<Reply> request(LongFunction<? extends ClientMessage> message) {
        ProtocolConnection open = connection;
        if (open == null || !open.isOpen()) {
            return CompletableFuture.failedFuture(new IOException("not connected to the server at " + server()));
        }
        return open.request(message);
    }

    /**
     * Sends a message that gets no reply.
     *
     * @throws IOException when no connection is open or writing fails
     */
    public void send(LongFunction<? extends ClientMessage> message) throws IOException {
        ProtocolConnection open = connection;
        if (open == null) {
            throw new IOException("not connected to the server at " + server());
        }
        open.send(message);
    }

    /** Closes the connection and connects no more; the listener hears nothing of it. */
    @Override
    public void close() {
        closed = true;
        thread.interrupt();
        ProtocolConnection open = connection;
        if (open != null) {
            open.close();
        }
    }

    private void run() {
        try {
            connectWhileOpen();
        } finally {
            ProtocolConnection open = connection;
            if (open != null) {
                open.close();
            }
        }
    }

    private void connectWhileOpen() {
        int retries = 0;
        while (!closed) {
            String reason;
            boolean forGood = false;
            try {
                Attempt attempt = new Attempt();
                connection = ProtocolConnection.connect(host, port, Role.VIEWER, "orchard-viewer", token,
                        operatorToken, attempt);
                attempt.announce();
                retries = 0;
                LOG.info("connected to the server at {}", server());
                listener.welcomed(connection.welcome());
                reason = attempt.end();
            } catch (IOException e) {
                reason = "cannot connect to the server at " + server() + ": " + e.getMessage();
                forGood = e.getCause() instanceof HandshakeRefusedException refused && refused.isFinal();
            } catch (InterruptedException e) {
                return;
            }
            if (closed) {
                return;
            }
            Duration wait = backoff == null || forGood ? null : backoff.before(++retries);
            if (wait == null) {
                LOG.warn("{}; not connecting again", reason);
            } else {
                LOG.warn("{}; connecting again in {}", reason, seconds(wait));
            }
            listener.ended(reason, wait);
            if (wait == null) {
                return;
            }
            try {
                Thread.sleep(wait.toMillis());
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    /** A wait in words: "0.5 s". */
    public static String seconds(Duration wait) {
        return String.format(Locale.ROOT, "%.1f s", wait.toMillis() / 1000.0).replace(".0 s", " s");
    }

    /**
     * One connection's messages, handed on in order, and how it ended: the last message (an
     * {@code Error} when the server closed the connection for a reason) and the cause of the close.
     */
    private final class Attempt implements ProtocolConnection.Listener {

        private final CompletableFuture<Throwable> closedBy = new CompletableFuture<>();
        private volatile ServerMessage last;
        private boolean announced;

        /** Tells the listener of the connection once, before its first message, whichever thread comes first. */
        synchronized void announce() {
            if (!announced) {
                announced = true;
                listener.connected();
            }
        }

        @Override
        public void onMessage(ServerMessage message) {
            announce();
            last = message;
            listener.received(message);
        }

        @Override
        public void onClosed(Throwable cause) {
            // A clean end of the stream has no cause; the future holds a marker instead of null.
            closedBy.complete(cause == null ? new EndOfStream() : cause);
        }

        /** Waits until the connection ends and says why. */
        String end() throws InterruptedException {
            Throwable cause;
            try {
                cause = closedBy.get();
            } catch (ExecutionException e) {
                cause = e.getCause();
            }
            String lost = "lost the connection to the server at " + server() + ": ";
            if (last instanceof ErrorMessage error) {
                return lost + "the server closed it with " + error.code().wireName() + ": " + error.text();
            }
            if (cause instanceof EndOfStream) {
                return lost + "the server closed it (end of stream)";
            }
            return lost + cause.getMessage();
        }
    }

    /** The marker of a connection the server ended without an error. */
    private static final class EndOfStream extends Exception {
        private static final long serialVersionUID = 1L;

        EndOfStream() {
            super("end of stream", null, false, false);
        }
    }
}
