package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.ClockMode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Each client is answered in the protocol version it spoke, on a real server over a raw socket:
 * the {@code Welcome} repeats the hello's version, and a version 1 client is told only what
 * version 1 knows.
 */
class ProtocolVersionsTest {

    private final MessageCodec codec = new MessageCodec();
    private WorldServer server;

    @BeforeEach
    void start() throws IOException {
        server = WorldServer.builder().port(0).seed(11).clock(ClockMode.REALTIME).operatorToken("op-4411").start();
    }

    @AfterEach
    void stop() {
        server.close();
    }

    /** Sends each line and returns the first answer to the last one, skipping the game's traffic. */
    private ServerMessage exchange(Socket socket, String... lines) throws IOException {
        socket.setSoTimeout(10_000);
        for (String line : lines) {
            socket.getOutputStream().write((line + "\n").getBytes(StandardCharsets.UTF_8));
        }
        socket.getOutputStream().flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        ServerMessage answer = null;
        for (int i = 0; i < lines.length; i++) {
            String line;
            do {
                line = in.readLine();
                assertThat(line).as("an answer to line %d", i + 1).isNotNull();
                answer = codec.decodeServer(line);
            } while (!(answer instanceof WelcomeMessage || answer instanceof ErrorMessage));
        }
        return answer;
    }

    private static String hello(int version) {
        return "{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":" + version + ",\"role\":\"viewer\",\"client\":\"v"
                + version + "\"}";
    }

    @ParameterizedTest(name = "version {0}")
    @ValueSource(ints = {1, 2})
    void theWelcomeRepeatsTheVersionTheClientSpoke(int version) throws IOException {
        try (Socket socket = new Socket("127.0.0.1", server.port())) {
            ServerMessage welcome = exchange(socket, hello(version));

            assertThat(welcome).isInstanceOfSatisfying(WelcomeMessage.class, w -> {
                assertThat(w.protocolVersion()).isEqualTo(version);
                assertThat(w.seq()).isEqualTo(1);
            });
        }
    }

    @Test
    void aVersion1ClientsGameControlIsRefusedWithACodeVersion1Knows() throws IOException {
        try (Socket socket = new Socket("127.0.0.1", server.port())) {
            ServerMessage refused = exchange(socket, hello(1), "{\"type\":\"GameControl\",\"seq\":2,\"command\":\"pause\"}");

            assertThat(refused).isInstanceOfSatisfying(ErrorMessage.class, error -> {
                assertThat(error.seq()).isEqualTo(2);
                assertThat(error.code()).isEqualTo(ErrorCode.WRONG_ROLE);
            });
        }
    }

    @Test
    void aVersion2ClientsGameControlIsForbidden() throws IOException {
        try (Socket socket = new Socket("127.0.0.1", server.port())) {
            ServerMessage refused = exchange(socket, hello(2), "{\"type\":\"GameControl\",\"seq\":2,\"command\":\"pause\"}");

            assertThat(refused).isInstanceOfSatisfying(ErrorMessage.class,
                    error -> assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN));
        }
    }
}
