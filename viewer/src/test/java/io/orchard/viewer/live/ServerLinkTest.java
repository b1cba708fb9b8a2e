package io.orchard.viewer.live;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.server.WorldServer;
import io.orchard.server.net.NetLimits;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.slf4j.LoggerFactory;

/**
 * The viewer's link against real servers: when the connection ends it says why, in its log and to
 * the viewer, and connects again, with growing waits, to a server started anew on the same port,
 * whose snapshot it then shows; a refusal for good is not tried again.
 */
class ServerLinkTest {

    private static final Backoff QUICK = new Backoff(Duration.ofMillis(100), Duration.ofMillis(400));

    /** What the link told, in order: "connected", the welcome, the messages, and how each connection ended. */
    private final BlockingQueue<Object> heard = new LinkedBlockingQueue<>();
    private final List<AutoCloseable> open = new ArrayList<>();
    private final ListAppender<ILoggingEvent> log = new ListAppender<>();

    /** How a connection ended, as the link told it. */
    record Ended(String reason, Duration retryIn) {}

    @BeforeEach
    void listenToTheLog() {
        log.start();
        ((Logger) LoggerFactory.getLogger(ServerLink.class)).addAppender(log);
    }

    @AfterEach
    void closeAll() throws Exception {
        ((Logger) LoggerFactory.getLogger(ServerLink.class)).detachAppender(log);
        for (int i = open.size() - 1; i >= 0; i--) {
            open.get(i).close();
        }
    }

    private ServerLink link(int port, String operatorToken, Backoff backoff) {
        ServerLink link = new ServerLink("127.0.0.1", port, null, operatorToken, backoff, new ServerLink.Listener() {
            @Override
            public void connected() {
                heard.add("connected");
            }

            @Override
            public void welcomed(WelcomeMessage welcome) {
                heard.add(welcome);
            }

            @Override
            public void received(ServerMessage message) {
                heard.add(message);
            }

            @Override
            public void ended(String reason, Duration retryIn) {
                heard.add(new Ended(reason, retryIn));
            }
        });
        open.add(link);
        link.start();
        return link;
    }

    private WorldServer server(WorldServer.Builder builder) throws IOException {
        WorldServer server = builder.start();
        open.add(server);
        return server;
    }

    /** The next thing the link told of this type, skipping the rest. */
    private <T> T next(Class<T> type) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (System.nanoTime() < end) {
            Object event = heard.poll(100, TimeUnit.MILLISECONDS);
            if (type.isInstance(event)) {
                return type.cast(event);
            }
        }
        throw new AssertionError("the link told no " + type.getSimpleName());
    }

    private void nextConnected() throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (System.nanoTime() < end) {
            if ("connected".equals(heard.poll(100, TimeUnit.MILLISECONDS))) {
                return;
            }
        }
        throw new AssertionError("the link did not connect");
    }

    private List<String> logged() {
        return log.list.stream().map(ILoggingEvent::getFormattedMessage).toList();
    }

    @Test
    void aServerStoppedAndStartedAgainOnTheSamePortIsWatchedAgainAndTheLogSaysWhy() throws Exception {
        WorldServer first = server(WorldServer.builder().port(0).seed(1).clock(ClockMode.REALTIME));
        int port = first.port();
        link(port, null, QUICK);
        nextConnected();
        WorldSnapshotMessage before = next(WorldSnapshotMessage.class);

        first.close();
        open.remove(first);
        Ended lost = next(Ended.class);
        WorldServer second = server(WorldServer.builder().port(port).seed(2).clock(ClockMode.REALTIME));
        nextConnected();
        WorldSnapshotMessage after = next(WorldSnapshotMessage.class);

        assertThat(lost.reason()).isEqualTo("lost the connection to the server at 127.0.0.1:" + port
                + ": the server closed it (end of stream)");
        assertThat(lost.retryIn()).isEqualTo(QUICK.first());
        assertThat(logged()).contains(lost.reason() + "; connecting again in 0.1 s",
                "connected to the server at 127.0.0.1:" + port);
        assertThat(after.obstacles()).as("the world of the server started again").isNotEqualTo(before.obstacles());
        assertThat(second.port()).isEqualTo(port);
    }

    @Test
    void aServerThatIsFullIsNamedWithItsReasonAndTriedAgainUntilThereIsRoom() throws Exception {
        WorldServer server = server(WorldServer.builder().port(0).seed(1)
                .limits(NetLimits.DEFAULT.withMaxConnections(1)));
        ProtocolConnection occupant = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "first",
                message -> { });
        link(server.port(), null, QUICK);

        Ended refused = next(Ended.class);
        occupant.close();
        nextConnected();

        assertThat(refused.reason()).startsWith("cannot connect to the server at 127.0.0.1:" + server.port() + ": ")
                .contains("too_many_agents: the server takes at most 1 connections; try again later");
        assertThat(refused.retryIn()).isNotNull();
        assertThat(next(WorldSnapshotMessage.class)).isNotNull();
    }

    @Test
    void aWrongOperatorTokenIsRefusedForGoodAndNotTriedAgain() throws Exception {
        WorldServer server = server(WorldServer.builder().port(0).seed(1).operatorToken("op-right"));
        link(server.port(), "op-wrong", QUICK);

        Ended refused = next(Ended.class);
        Thread.sleep(3 * QUICK.most().toMillis());

        assertThat(refused.reason()).endsWith("unauthorized: wrong operator token");
        assertThat(refused.retryIn()).as("no next attempt").isNull();
        assertThat(heard).as("what the link told after").isEmpty();
        assertThat(logged()).contains(refused.reason() + "; not connecting again");
    }

    @Test
    void theErrorAServerClosesTheConnectionWithIsTheReasonGiven() throws Exception {
        MessageCodec codec = new MessageCodec();
        ServerSocket listener = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        open.add(listener);
        Thread peer = new Thread(() -> {
            try (Socket socket = listener.accept()) {
                socket.getInputStream().read(new byte[256]); // the hello
                OutputStream out = socket.getOutputStream();
                out.write(codec.encodeLine(new WelcomeMessage(0, 2, "test", Role.VIEWER, new Bounds(-1, -1, 1, 1), 20,
                        ClockMode.REALTIME, 0)));
                out.write(codec.encodeLine(new ErrorMessage(0, ErrorCode.SLOW_CONSUMER,
                        "16777216 bytes wait for this client; closing")));
                out.flush();
            } catch (IOException e) {
                // the test is over
            }
        });
        peer.setDaemon(true);
        peer.start();
        link(listener.getLocalPort(), null, null);

        Ended ended = next(Ended.class);

        assertThat(ended.reason()).isEqualTo("lost the connection to the server at 127.0.0.1:"
                + listener.getLocalPort() + ": the server closed it with slow_consumer: 16777216 bytes wait for this "
                + "client; closing");
        assertThat(ended.retryIn()).as("a link without a backoff connects once").isNull();
    }

    @Test
    void theWaitsGrowFromTheFirstToTheLongest() {
        Backoff backoff = new Backoff(Duration.ofMillis(500), Duration.ofSeconds(3));

        assertThat(List.of(1, 2, 3, 4, 5)).extracting(backoff::before).containsExactly(Duration.ofMillis(500),
                Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(3), Duration.ofSeconds(3));
        assertThat(ServerLink.seconds(Duration.ofMillis(500))).isEqualTo("0.5 s");
        assertThat(ServerLink.seconds(Duration.ofSeconds(2))).isEqualTo("2 s");
    }
}
