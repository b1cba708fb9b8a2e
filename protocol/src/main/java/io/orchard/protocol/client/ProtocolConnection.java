package io.orchard.protocol.client;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolException;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.KeepAliveMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Form;
import io.orchard.protocol.value.Role;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.net.UnknownHostException;
import java.time.Duration;
import java.util.Locale;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongFunction;

/**
 * A client's connection to an Orchard server, on the JDK alone: a socket, the line framing, one
 * reader thread that hands every server message to a {@link Listener}, and sends that number each
 * message with the next {@code seq}.
 *
 * <p>{@link #connect} performs the handshake before it returns: it sends {@code Hello} and waits for
 * {@code Welcome}. An agent control client reads the lean form of perceptions ({@link Form}): the
 * server sends each perception as one short {@code LeanPerception} line, which the connection hands
 * on as the {@code Perception}, {@code LandmarkPerception} and {@code CastlePerception} it stands
 * for, so that a listener sees the same messages whichever form travelled. Sending is thread-safe. The listener is called on the reader thread, one message
 * at a time, in the order the server sent them; it should hand long work to another thread.
 *
 * <pre>{@code
 * try (ProtocolConnection connection = ProtocolConnection.connect("localhost", 7557, Role.AGENT,
 *         "my-agent", message -> System.out.println(message))) {
 *     connection.request(seq -> new RegisterMessage(seq, "Guppy", body, null)).get();
 * }
 * }</pre>
 */
public final class ProtocolConnection implements AutoCloseable {

    /** Receives what the server sends, on the connection's reader thread. */
    @FunctionalInterface
    public interface Listener {

        /** A message from the server (replies included: they also complete their {@link #request}). */
        void onMessage(ServerMessage message);

        /**
         * The connection closed: {@code cause} is null after {@link #close()} or a clean end of the
         * stream, otherwise what went wrong.
         */
        default void onClosed(Throwable cause) {}
    }

    private static final Duration HANDSHAKE_TIMEOUT = Duration.ofSeconds(10);

    private final Socket socket;
    private final OutputStream out;
    private final MessageCodec codec;
    private final Listener listener;
    private final AtomicLong nextSeq = new AtomicLong(1);
    private final Map<Long, CompletableFuture<Reply>> pending = new ConcurrentHashMap<>();
    private final AtomicBoolean closed = new AtomicBoolean();
    private final CompletableFuture<WelcomeMessage> welcome = new CompletableFuture<>();
    private final Thread readerThread;

    private ProtocolConnection(Socket socket, MessageCodec codec, Listener listener) throws IOException {
        this.socket = socket;
        this.out = new BufferedOutputStream(socket.getOutputStream(), 16 * 1024);
        this.codec = codec;
        this.listener = listener;
        this.readerThread = new Thread(this::readLoop, "orchard-connection-" + socket.getLocalPort());
        this.readerThread.setDaemon(true);
    }

    /**
     * Connects to a server and performs the handshake.
     *
     * @param host       the server's host name or address
     * @param port       the server's port
     * @param role       what this client is: an agent control client or a viewer
     * @param clientName a name for this program, for the server's logs
     * @param listener   receives every server message after the welcome
     * @return the open connection
     * @throws IOException when the server cannot be reached or refuses the handshake; the message
     *                     names the host and port and what went wrong: an {@link UnknownHostException}
     *                     for a host with no address, a {@link ConnectException} when no server
     *                     listens there, one caused by a {@link HandshakeRefusedException} when the
     *                     server answered the hello with an error
     */
    public static ProtocolConnection connect(String host, int port, Role role, String clientName, Listener listener)
            throws IOException {
        return connect(host, port, role, clientName, null, listener);
    }

    /**
     * Connects to a server that requires a token and performs the handshake. An agent control client
     * reads perceptions in the lean form and still has its accepted moves answered
     * ({@link Form#LEAN_PERCEPTION}, {@link Form#ACCEPTED_MOVES}); a viewer asks for no other form.
     *
     * @param token the server's shared secret, or null when it requires none
     * @see #connect(String, int, Role, String, Listener)
     */
    public static ProtocolConnection connect(String host, int port, Role role, String clientName, String token,
                                             Listener listener) throws IOException {
        return handshake(host, port, role, clientName, token, null, defaultForms(role), listener);
    }

    /**
     * Connects as the game's operator, who may start, pause and resume the game with
     * {@code GameControl}, and performs the handshake. A server refuses a wrong operator token as it
     * refuses a wrong token: the handshake fails with {@code unauthorized}.
     *
     * @param token         the server's shared secret, or null when it requires none
     * @param operatorToken the server's operator token, or null to connect as an ordinary client
     * @see #connect(String, int, Role, String, Listener)
     */
    public static ProtocolConnection connect(String host, int port, Role role, String clientName, String token,
                                             String operatorToken, Listener listener) throws IOException {
        return handshake(host, port, role, clientName, token, operatorToken, defaultForms(role), listener);
    }

    /**
     * Connects to a server, asking for these forms of its lines, and performs the handshake. Without
     * {@link Form#ACCEPTED_MOVES} beside {@link Form#LEAN_PERCEPTION} an accepted move has no reply,
     * so that a {@link #request} of a {@code Move} completes only when it is blocked or rejected.
     *
     * @param token the server's shared secret, or null when it requires none
     * @param reads the forms to ask for besides the ordinary lines; empty for none
     * @see #connect(String, int, Role, String, Listener)
     */
    public static ProtocolConnection connect(String host, int port, Role role, String clientName, String token,
                                             Set<Form> reads, Listener listener) throws IOException {
        return handshake(host, port, role, clientName, token, null, reads, listener);
    }

    /** An agent's client reads the lean form, with its accepted moves answered; a viewer the ordinary lines. */
    private static Set<Form> defaultForms(Role role) {
        return role == Role.AGENT ? EnumSet.of(Form.LEAN_PERCEPTION, Form.ACCEPTED_MOVES) : EnumSet.noneOf(Form.class);
    }

    private static ProtocolConnection handshake(String host, int port, Role role, String clientName, String token,
                                                String operatorToken, Set<Form> reads, Listener listener)
            throws IOException {
        Objects.requireNonNull(listener, "listener");
        // Made before connecting: the server's handshake deadline runs from the connection, and a
        // cold JVM's first codec and first encoding can take seconds on a busy machine.
        List<String> forms = reads.isEmpty() ? null : Form.names(reads);
        MessageCodec codec = new MessageCodec();
        byte[] hello = codec.encodeLine(new HelloMessage(0, ProtocolVersion.CURRENT, role, clientName, token,
                operatorToken, forms));
        Socket socket = new Socket();
        try {
            socket.setTcpNoDelay(true);
            open(socket, host, port);
            ProtocolConnection connection = new ProtocolConnection(socket, codec, listener);
            connection.readerThread.start();
            try {
                connection.writeNow(hello);
            } catch (IOException writeFailed) {
                // A server that refuses at once (full, say) may close before reading the hello, and
                // the reader may have taken its refusal and closed the socket under the write:
                // the refusal, not the failed write, is the reason.
                connection.throwRefusal();
                throw writeFailed;
            }
            connection.awaitWelcome();
            return connection;
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    /**
     * Connects the socket, in words that name the server and say what went wrong: the JDK's own
     * ("Connection refused", or just the host's name) do neither.
     */
    private static void open(Socket socket, String host, int port) throws IOException {
        InetSocketAddress address = new InetSocketAddress(host, port);
        if (address.isUnresolved()) {
            throw new UnknownHostException("unknown host '" + host + "': no address found for it; expected a host"
                    + " name or address that resolves, such as localhost or 192.168.1.20");
        }
        String server = host + ":" + port;
        try {
            socket.connect(address, (int) HANDSHAKE_TIMEOUT.toMillis());
        } catch (ConnectException e) {
            boolean refused = String.valueOf(e.getMessage()).toLowerCase(Locale.ROOT).contains("refused");
            throw because(new ConnectException(refused
                    ? "no server is listening at " + server + " (connection refused)"
                    : "cannot connect to " + server + ": " + e.getMessage()), e);
        } catch (SocketTimeoutException e) {
            throw because(new SocketTimeoutException("no answer from " + server + " within "
                    + HANDSHAKE_TIMEOUT.toSeconds() + " s: is the host right, and is the port open to this machine?"), e);
        } catch (SocketException e) {
            throw because(new SocketException("cannot connect to " + server + ": " + e.getMessage()), e);
        }
    }

    private static <T extends IOException> T because(T failure, IOException cause) {
        failure.initCause(cause);
        return failure;
    }

    /** The server's welcome: the world's bounds, the tick rate, the clock mode. */
    public WelcomeMessage welcome() {
        return welcome.join();
    }

    /**
     * Sends a message built with the next sequence number.
     *
     * @param message builds the message from its {@code seq}, e.g. {@code seq -> new MoveMessage(seq, ...)}
     * @return the sequence number used
     * @throws IOException when the connection is closed or writing fails
     */
    public long send(LongFunction<? extends ClientMessage> message) throws IOException {
        long seq = nextSeq.getAndIncrement();
        sendNow(message.apply(seq));
        return seq;
    }

    /**
     * Sends a {@code KeepAlive} with {@code seq} 0, outside the numbering of the other messages
     * (numbers need not be unique, and a keep-alive has no reply): a keep-alive goes when the wall
     * clock says so, and numbering it would make the numbers of everything sent after it, which a
     * recording keeps, depend on the wall clock.
     *
     * @throws IOException when the connection is closed or writing fails
     */
    public void keepAlive() throws IOException {
        sendNow(new KeepAliveMessage(0));
    }

    /**
     * Sends a message and returns the server's reply to it: the result, or the
     * {@link ErrorMessage} if the server refused it.
     */
    public CompletableFuture<Reply> request(LongFunction<? extends ClientMessage> message) {
        long seq = nextSeq.getAndIncrement();
        CompletableFuture<Reply> reply = new CompletableFuture<>();
        pending.put(seq, reply);
        try {
            sendNow(message.apply(seq));
        } catch (IOException | RuntimeException e) {
            pending.remove(seq);
            reply.completeExceptionally(e);
        }
        return reply;
    }

    /** Whether the connection is still open. */
    public boolean isOpen() {
        return !closed.get();
    }

    /** Closes the connection; the listener hears {@code onClosed(null)}. Idempotent. */
    @Override
    public void close() {
        shutdown(null);
    }

    private void sendNow(ClientMessage message) throws IOException {
        if (closed.get()) {
            throw new IOException("connection is closed");
        }
        writeNow(codec.encodeLine(message));
    }

    private void writeNow(byte[] line) throws IOException {
        synchronized (out) {
            out.write(line);
            out.flush();
        }
    }

    /** Throws the server's refusal of the handshake, if it sent one before the connection ended. */
    private void throwRefusal() throws IOException {
        try {
            awaitWelcome();
        } catch (IOException ended) {
            if (ended.getCause() instanceof HandshakeRefusedException) {
                throw ended;
            }
        }
    }

    private void awaitWelcome() throws IOException {
        try {
            welcome.get(HANDSHAKE_TIMEOUT.toMillis(), java.util.concurrent.TimeUnit.MILLISECONDS);
        } catch (java.util.concurrent.ExecutionException e) {
            throw new IOException("handshake failed: " + e.getCause().getMessage(), e.getCause());
        } catch (java.util.concurrent.TimeoutException e) {
            throw new IOException("no welcome from the server within " + HANDSHAKE_TIMEOUT.toSeconds() + " s");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted during the handshake", e);
        }
    }

    private void readLoop() {
        Throwable failure = null;
        try {
            LineReader lines = new LineReader(socket.getInputStream(), MessageCodec.MAX_LARGE_LINE_BYTES);
            byte[] line;
            while ((line = lines.readLine()) != null) {
                ServerMessage message;
                try {
                    message = codec.decodeServer(line);
                } catch (ProtocolException e) {
                    // A newer server may send types or values this client does not know: skip them.
                    continue;
                }
                dispatch(message);
            }
        } catch (IOException e) {
            failure = closed.get() ? null : e;
        } catch (RuntimeException e) {
            failure = e;
        }
        shutdown(failure);
    }

    private void dispatch(ServerMessage message) {
        if (!welcome.isDone()) {
            if (message instanceof WelcomeMessage hello) {
                welcome.complete(hello);
            } else if (message instanceof ErrorMessage error) {
                welcome.completeExceptionally(new HandshakeRefusedException(error));
            }
            return;
        }
        if (message instanceof Reply reply) {
            CompletableFuture<Reply> waiting = pending.remove(reply.seq());
            if (waiting != null) {
                waiting.complete(reply);
            }
        }
        if (message instanceof LeanPerceptionMessage lean) {
            listener.onMessage(lean.toPerception());
            listener.onMessage(lean.toLandmarks());
            listener.onMessage(lean.toCastle());
        } else {
            listener.onMessage(message);
        }
    }

    private void shutdown(Throwable cause) {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing is best effort; the socket is unusable either way
        }
        IOException gone = new IOException("connection closed", cause);
        welcome.completeExceptionally(gone);
        pending.values().forEach(reply -> reply.completeExceptionally(gone));
        pending.clear();
        listener.onClosed(cause);
    }
}
