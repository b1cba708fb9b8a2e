package io.orchard.agents;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Role;
import java.io.IOException;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The agent's connection to the server. What the server sends, and the instructions other threads
 * hand the agent, wait in one queue for the controller's thread. What the agent sends goes out no
 * faster than the server allows ({@link Throttle}), and a message the server will answer is kept
 * by its sequence number until the answer comes, so that the answer can be read with it. When the
 * agent has said nothing for a while, it says "still here" ({@link Silence}).
 */
final class Session {

    private static final Logger log = LoggerFactory.getLogger(Session.class);

    /** A console line or relayed instruction, queued for the controller's thread. */
    record Instruction(String text, String from) {}

    /** The connection closed; the cause is null when it closed cleanly. */
    record Closed(@Nullable Throwable cause) {}

    private final String agent;
    private final BlockingQueue<Object> inbox = new LinkedBlockingQueue<>();
    private final Map<Long, ClientMessage> awaiting = new HashMap<>();
    private final Throttle throttle = new Throttle(Throttle.RATE, Throttle.BURST);
    private final Silence silence = new Silence();
    private volatile ProtocolConnection connection;
    private volatile boolean stopping;

    Session(String agent) {
        this.agent = agent;
    }

    /** Connects; from now on what the server sends waits in the queue. */
    void open(String host, int port, @Nullable String token) throws IOException {
        connection = ProtocolConnection.connect(host, port, Role.AGENT, "orchard-agent-" + agent, token,
                new ProtocolConnection.Listener() {
                    @Override
                    public void onMessage(ServerMessage message) {
                        inbox.add(message);
                    }

                    @Override
                    public void onClosed(Throwable cause) {
                        inbox.add(new Closed(cause));
                    }
                });
        silence.watch(this::keepAlive);
    }

    /** Says "still here" to a server of version 2 or later, on the silence's thread. */
    private void keepAlive() {
        ProtocolConnection open = connection;
        if (open != null && open.isOpen() && open.welcome().protocolVersion() >= 2) {
            try {
                open.keepAlive();
            } catch (IOException e) {
                log.debug("{}: could not send a keep-alive: {}", agent, e.getMessage());
            }
        }
    }

    /** The server's welcome, the first thing it sends. */
    WelcomeMessage welcome() {
        return connection.welcome();
    }

    /** Sends a message and hands back the server's reply to it when it comes. */
    CompletableFuture<Reply> request(LongFunction<? extends ClientMessage> message) {
        silence.broken();
        return connection.request(message);
    }

    /**
     * Sends a message built for its sequence number, waiting for the throttle if need be.
     *
     * @return the sequence number, or -1 when the connection is not open or the message could
     *         not be sent
     */
    long send(LongFunction<? extends ClientMessage> message) {
        ProtocolConnection open = connection;
        if (open == null || !open.isOpen()) {
            return -1;
        }
        try {
            throttle.acquire();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return -1;
        }
        try {
            silence.broken();
            return open.send(seq -> {
                ClientMessage built = message.apply(seq);
                if (!(built instanceof EndTurnMessage || built instanceof SayMessage)) {
                    awaiting.put(seq, built); // the server answers it: remember what it was
                }
                return built;
            });
        } catch (IOException e) {
            log.debug("{}: could not send: {}", agent, e.getMessage());
            return -1;
        }
    }

    /** A tick of a lockstep game began: what the server allows for it may be sent. */
    void lockstepTicked() {
        throttle.ticked();
    }

    /** Keep-alives after this much silence instead of {@link Silence#EVERY}. */
    void keepAliveEvery(Duration silence) {
        this.silence.every(silence);
    }

    /** The message the server answered under this sequence number; null when none is awaited. */
    @Nullable ClientMessage answered(long seq) {
        return awaiting.remove(seq);
    }

    /** Queues an instruction for the controller's thread. Safe from any thread. */
    void instruct(Instruction instruction) {
        inbox.add(instruction);
    }

    /** The next event (a {@link ServerMessage}, an {@link Instruction} or {@link Closed}), as long as it takes. */
    Object next() throws InterruptedException {
        return inbox.take();
    }

    /** The next event, or null when none came within {@code millis}. */
    @Nullable Object next(long millis) throws InterruptedException {
        return inbox.poll(millis, TimeUnit.MILLISECONDS);
    }

    /** Leaves: the connection closes, and its closing is no error. Safe from any thread. */
    void stop() {
        stopping = true;
        close();
    }

    /** Whether {@link #stop()} was called. */
    boolean stopping() {
        return stopping;
    }

    /** Closes the connection, if it was opened. */
    void close() {
        silence.unwatch();
        ProtocolConnection open = connection;
        if (open != null) {
            open.close();
        }
    }
}
