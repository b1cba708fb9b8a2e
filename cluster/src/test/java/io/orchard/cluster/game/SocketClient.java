package io.orchard.cluster.game;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Role;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.function.Predicate;

/**
 * A client over a real socket for tests, with the messages the test builds sent as they are (their
 * own sequence numbers): it says hello, checks the welcome, and keeps everything the server sends
 * after it in a {@link TestSession}, where the test's agents read it.
 */
final class SocketClient implements AutoCloseable {

    private static final MessageCodec CODEC = new MessageCodec();

    private final Socket socket;
    private final OutputStream out;
    private final TestSession heard;

    private SocketClient(Socket socket, TestSession heard) throws IOException {
        this.socket = socket;
        this.out = socket.getOutputStream();
        this.heard = heard;
    }

    /** Connects to {@code port} on loopback as {@code role}, the operator when {@code operatorToken} is given. */
    static SocketClient connect(int port, Role role, String operatorToken) throws IOException {
        Socket socket = new Socket();
        socket.setTcpNoDelay(true);
        socket.connect(new InetSocketAddress("127.0.0.1", port), 10_000);
        SocketClient client = new SocketClient(socket, new TestSession(port, role));
        client.send(new HelloMessage(0, ProtocolVersion.CURRENT, role, "test", null, operatorToken, null));
        BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        ServerMessage welcome = CODEC.decodeServer(in.readLine());
        if (!(welcome instanceof WelcomeMessage)) {
            socket.close();
            throw new IOException("no welcome from port " + port + ": " + welcome);
        }
        Thread reader = new Thread(() -> {
            try {
                for (String line = in.readLine(); line != null; line = in.readLine()) {
                    client.heard.send(CODEC.decodeServer(line));
                }
            } catch (IOException e) {
                // closed
            }
        }, "test-client-" + port);
        reader.setDaemon(true);
        reader.start();
        return client;
    }

    /** Where the test's agents read what the server sent. */
    TestSession heard() {
        return heard;
    }

    /** Sends these messages, in order. */
    synchronized void send(List<ClientMessage> messages) throws IOException {
        for (ClientMessage message : messages) {
            out.write(CODEC.encodeLine(message));
        }
        out.flush();
    }

    /** Sends one message. */
    void send(ClientMessage message) throws IOException {
        send(List.of(message));
    }

    /** Waits up to a minute for a message that {@code wanted} matches, among all sent so far; returns it. */
    ServerMessage await(Predicate<ServerMessage> wanted, String what) throws InterruptedException {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (System.nanoTime() < deadline) {
            List<ServerMessage> all = heard.all();
            for (int i = all.size() - 1; i >= 0; i--) {
                if (wanted.test(all.get(i))) {
                    return all.get(i);
                }
            }
            Thread.sleep(2);
        }
        throw new AssertionError("no " + what + " within a minute; heard " + heard.all());
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
