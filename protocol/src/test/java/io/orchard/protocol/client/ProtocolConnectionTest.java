package io.orchard.protocol.client;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Form;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The connection against a scripted peer on a real loopback socket. */
class ProtocolConnectionTest {

    private final MessageCodec codec = new MessageCodec();
    private ServerSocket server;
    private final List<String> received = new CopyOnWriteArrayList<>();

    @AfterEach
    void closeServer() throws IOException {
        if (server != null) {
            server.close();
        }
    }

    /** Starts a peer on an ephemeral port that answers each client line with whatever {@code script} writes. */
    private int peer(BiConsumer<ClientMessage, OutputStream> script) throws IOException {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Thread thread = new Thread(() -> {
            try (Socket socket = server.accept()) {
                BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
                OutputStream out = socket.getOutputStream();
                String line;
                while ((line = in.readLine()) != null) {
                    received.add(line);
                    script.accept(codec.decodeClient(line), out);
                }
            } catch (IOException ignored) {
                // the test closed the connection
            }
        });
        thread.setDaemon(true);
        thread.start();
        return server.getLocalPort();
    }

    private void write(OutputStream out, ServerMessage message) {
        try {
            out.write(codec.encodeLine(message));
            out.flush();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private WelcomeMessage welcome(long seq) {
        return new WelcomeMessage(seq, 1, "test", Role.AGENT, new Bounds(-10, -10, 10, 10), 20, ClockMode.LOCKSTEP, 0);
    }

    @Test
    void connectPerformsTheHandshakeAndRequestGetsTheMatchingReply() throws Exception {
        int port = peer((message, out) -> {
            if (message instanceof HelloMessage hello) {
                write(out, welcome(hello.seq()));
            } else if (message instanceof MoveMessage move) {
                write(out, new TickMessage(1, 0.05)); // unrelated traffic first
                write(out, new ActionResultMessage(move.seq(), move.agent(), "Move", Outcome.ACCEPTED, null, move.to(), 0.5));
            }
        });
        BlockingQueue<ServerMessage> heard = new LinkedBlockingQueue<>();
        try (ProtocolConnection connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test", heard::add)) {
            assertThat(connection.welcome().tickRate()).isEqualTo(20);
            CompletableFuture<Reply> reply = connection.request(seq -> new MoveMessage(seq, "Guppy", Vec3.ZERO, new Vec3(1, 0, 1)));
            ActionResultMessage result = (ActionResultMessage) reply.get(5, TimeUnit.SECONDS);
            assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED);
            assertThat(result.seq()).isEqualTo(codec.decodeClient(received.get(1)).seq());
            assertThat(heard.poll(5, TimeUnit.SECONDS)).isInstanceOf(TickMessage.class);
        }
        assertThat(received.get(0)).startsWith("{\"type\":\"Hello\"");
    }

    @Test
    void anAgentReadsTheLeanFormAndHearsTheThreePerceptionMessagesItStandsFor() throws Exception {
        PerceptionMessage seen = new PerceptionMessage(7, "Guppy", new Vec3(1.25, 0, -4.5), 0.25,
                List.of(new PerceivedObject("T17", ObjectKind.TREE, new RelativePosition(6.5, -0.4), 1.5, 6)),
                List.of(), List.of(new PerceivedFruit("F1", FruitKind.BANANA, new Vec3(2, 0.25, -5), 0.25, null)));
        LandmarkPerceptionMessage landmarks = new LandmarkPerceptionMessage(7, "Guppy", null, List.of());
        CastlePerceptionMessage castle = new CastlePerceptionMessage(7, "Guppy", Sector.EAST);
        int port = peer((message, out) -> {
            if (message instanceof HelloMessage hello) {
                write(out, welcome(hello.seq()));
                write(out, LeanPerceptionMessage.of(seen, landmarks, castle));
            }
        });
        BlockingQueue<ServerMessage> heard = new LinkedBlockingQueue<>();
        try (ProtocolConnection connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test", heard::add)) {
            assertThat(heard.poll(5, TimeUnit.SECONDS)).isEqualTo(seen);
            assertThat(heard.poll(5, TimeUnit.SECONDS)).isEqualTo(landmarks);
            assertThat(heard.poll(5, TimeUnit.SECONDS)).isEqualTo(castle);
        }
        HelloMessage hello = (HelloMessage) codec.decodeClient(received.get(0));
        assertThat(hello.reads()).containsExactly("LeanPerception", "AcceptedMoves");
    }

    @Test
    void aViewerAndAClientThatAsksForNoFormSendTheOrdinaryHello() throws Exception {
        for (Role role : Role.values()) {
            received.clear();
            int port = peer((message, out) -> {
                if (message instanceof HelloMessage hello) {
                    write(out, welcome(hello.seq()));
                }
            });
            Set<Form> none = EnumSet.noneOf(Form.class);
            try (ProtocolConnection connection = role == Role.AGENT
                    ? ProtocolConnection.connect("127.0.0.1", port, role, "test", null, none, message -> { })
                    : ProtocolConnection.connect("127.0.0.1", port, role, "test", message -> { })) {
                assertThat(connection.isOpen()).isTrue();
            }
            assertThat(received.get(0)).isEqualTo("{\"type\":\"Hello\",\"seq\":0,\"protocolVersion\":2,\"role\":\""
                    + role.wireName() + "\",\"client\":\"test\"}");
            server.close();
        }
    }

    @Test
    void linesOfUnknownTypesAreSkippedAndTheConnectionGoesOn() throws Exception {
        int port = peer((message, out) -> {
            if (message instanceof HelloMessage hello) {
                write(out, welcome(hello.seq()));
                try {
                    out.write("{\"type\":\"SomethingNewer\",\"tick\":1}\n".getBytes(StandardCharsets.UTF_8));
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
                write(out, new TickMessage(2, 0.1));
            }
        });
        BlockingQueue<ServerMessage> heard = new LinkedBlockingQueue<>();
        try (ProtocolConnection connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test", heard::add)) {
            assertThat(heard.poll(5, TimeUnit.SECONDS)).isEqualTo(new TickMessage(2, 0.1));
            assertThat(connection.isOpen()).isTrue();
        }
    }

    @Test
    void refusedHandshakeFailsConnectWithTheServersReason() throws IOException {
        int port = peer((message, out) -> write(out, new ErrorMessage(message.seq(), ErrorCode.VERSION_MISMATCH,
                "server speaks protocol 2, client 1")));
        assertThatThrownBy(() -> ProtocolConnection.connect("127.0.0.1", port, Role.VIEWER, "test", m -> { }))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("version_mismatch: server speaks protocol 2, client 1")
                .cause().isInstanceOfSatisfying(HandshakeRefusedException.class, refused -> {
                    assertThat(refused.error().code()).isEqualTo(ErrorCode.VERSION_MISMATCH);
                    assertThat(refused.isFinal()).as("the same hello is refused again").isTrue();
                });
    }

    @Test
    void anOperatorTokenTravelsInTheHelloAndAFullServerIsNotARefusalForGood() throws IOException {
        int port = peer((message, out) -> write(out, new ErrorMessage(message.seq(), ErrorCode.TOO_MANY_AGENTS,
                "the server takes at most 1 connections; try again later")));
        assertThatThrownBy(() -> ProtocolConnection.connect("127.0.0.1", port, Role.VIEWER, "test", null, "op-1",
                m -> { })).cause().isInstanceOfSatisfying(HandshakeRefusedException.class,
                        refused -> assertThat(refused.isFinal()).isFalse());
        assertThat(codec.decodeClient(received.get(0))).isInstanceOfSatisfying(HelloMessage.class,
                hello -> assertThat(hello.operatorToken()).isEqualTo("op-1"));
    }

    /**
     * A full server refuses at once and closes, before it reads the hello: the client's reader may
     * have taken the refusal and closed the socket before the hello is written. The refusal is the
     * reason, not the failed write ("Socket closed"), whichever thread gets there first.
     */
    @Test
    void aRefusalSentBeforeTheHelloIsReadIsTheReasonWhicheverThreadIsFirst() throws Exception {
        server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        byte[] refusal = codec.encodeLine(new ErrorMessage(0, ErrorCode.TOO_MANY_AGENTS,
                "the server takes at most 1 connections; try again later"));
        Thread refuser = new Thread(() -> {
            while (!server.isClosed()) {
                try (Socket socket = server.accept()) {
                    socket.getOutputStream().write(refusal);
                } catch (IOException closed) {
                    return;
                }
            }
        });
        refuser.setDaemon(true);
        refuser.start();
        int port = server.getLocalPort();

        for (int attempt = 0; attempt < 200; attempt++) {
            int number = attempt;
            assertThatThrownBy(() -> ProtocolConnection.connect("127.0.0.1", port, Role.VIEWER, "test", m -> { }))
                    .as("attempt %d", number)
                    .hasMessageContaining("too_many_agents: the server takes at most 1 connections")
                    .cause().isInstanceOf(HandshakeRefusedException.class);
        }
    }

    @Test
    void connectingWhereNoServerListensNamesTheHostAndPortAndSaysSo() throws IOException {
        int port;
        try (ServerSocket free = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = free.getLocalPort(); // closed again: nothing listens there
        }
        assertThatThrownBy(() -> ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test", m -> { }))
                .isInstanceOf(ConnectException.class)
                .hasMessage("no server is listening at 127.0.0.1:" + port + " (connection refused)");
    }

    @Test
    void connectingToAnUnknownHostNamesIt() {
        // .invalid is reserved: it never resolves (RFC 2606)
        assertThatThrownBy(() -> ProtocolConnection.connect("nosuchhost.invalid", 7557, Role.AGENT, "test", m -> { }))
                .isInstanceOf(UnknownHostException.class)
                .hasMessageStartingWith("unknown host 'nosuchhost.invalid'");
    }

    @Test
    void pendingRequestsFailWhenTheServerHangsUp() throws Exception {
        int port = peer((message, out) -> {
            if (message instanceof HelloMessage hello) {
                write(out, welcome(hello.seq()));
            } else {
                try {
                    server.close();
                    out.close();
                } catch (IOException ignored) {
                    // closing is the point
                }
            }
        });
        CompletableFuture<Throwable> closed = new CompletableFuture<>();
        ProtocolConnection connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test",
                new ProtocolConnection.Listener() {
                    @Override
                    public void onMessage(ServerMessage message) { }

                    @Override
                    public void onClosed(Throwable cause) {
                        closed.complete(cause);
                    }
                });
        CompletableFuture<Reply> reply = connection.request(seq -> new MoveMessage(seq, "Guppy", Vec3.ZERO, Vec3.ZERO));
        assertThatThrownBy(() -> reply.get(5, TimeUnit.SECONDS)).hasCauseInstanceOf(IOException.class);
        closed.get(5, TimeUnit.SECONDS);
        assertThat(connection.isOpen()).isFalse();
        assertThatThrownBy(() -> connection.send(seq -> new MoveMessage(seq, "Guppy", Vec3.ZERO, Vec3.ZERO)))
                .isInstanceOf(IOException.class);
    }

    @Test
    void lineReaderRefusesLinesBeyondItsBound() {
        byte[] data = ("short\n" + "x".repeat(100) + "\n").getBytes(StandardCharsets.UTF_8);
        LineReader reader = new LineReader(new java.io.ByteArrayInputStream(data), 50);
        assertThatThrownBy(() -> {
            assertThat(new String(reader.readLine(), StandardCharsets.UTF_8)).isEqualTo("short");
            reader.readLine();
        }).isInstanceOf(IOException.class).hasMessageContaining("longer than 50 bytes");
    }

    @Test
    void lineReaderSplitsLinesAcrossReads() throws IOException {
        java.io.InputStream trickle = new java.io.InputStream() {
            private final byte[] bytes = "ab\ncd\nlast".getBytes(StandardCharsets.UTF_8);
            private int i;

            @Override
            public int read() {
                return i < bytes.length ? bytes[i++] : -1;
            }

            @Override
            public int read(byte[] b, int off, int len) {
                if (i >= bytes.length) {
                    return -1;
                }
                b[off] = bytes[i++];
                return 1;
            }
        };
        LineReader reader = new LineReader(trickle, 100);
        assertThat(new String(reader.readLine(), StandardCharsets.UTF_8)).isEqualTo("ab");
        assertThat(new String(reader.readLine(), StandardCharsets.UTF_8)).isEqualTo("cd");
        assertThat(new String(reader.readLine(), StandardCharsets.UTF_8)).isEqualTo("last");
        assertThat(reader.readLine()).isNull();
    }
}
