package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Over real sockets, as a client writer following docs/protocol.md meets the server: what a client
 * that connects to a game under way is told, by protocol version and role, and the errors the
 * issue found, told in the protocol's words.
 */
class JoiningAGameUnderWayTest {

    private static final String BODY = "{\"radius\":0.5,\"height\":1.2,\"maxSpeed\":10,\"gripper\":{\"part\":\"hands\","
            + "\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},\"sight\":{\"range\":30,\"fieldOfView\":3.14}}";

    @TempDir
    Path dir;

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = open.size() - 1; i >= 0; i--) {
            open.get(i).close();
        }
    }

    private WorldServer started() throws IOException {
        Path scenario = dir.resolve("small.json");
        ScenarioFile.write(io.orchard.server.sim.TestWorlds.small().toScenario(), scenario);
        WorldServer server = WorldServer.builder().port(0).seed(11).scenario(scenario).clock(ClockMode.REALTIME)
                .tickRate(50).placement((name, radius) -> Map.of("Guppy", Vec3.ground(0, 0),
                        "Bunny", Vec3.ground(-20, -15)).get(name)).start();
        open.add(server);
        return server;
    }

    private Line connect(WorldServer server, int version, String role) throws IOException {
        Line client = new Line(server.port());
        open.add(client);
        client.send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":" + version + ",\"role\":\"" + role
                + "\",\"client\":\"late\"}");
        return client;
    }

    @Test
    void aClientThatComesLateHearsTheStartAndOnlyAViewerHearsTheSeed() throws Exception {
        WorldServer server = started();
        Line first = connect(server, 2, "agent");
        assertThat(first.read()).contains("\"type\":\"Welcome\"").endsWith(",\"timeLimit\":300.0,\"phase\":\"waiting\"}");
        first.send("{\"type\":\"Register\",\"seq\":2,\"name\":\"Guppy\",\"body\":" + BODY + "}");
        assertThat(first.readUntil("\"type\":\"Registered\"")).contains("\"seq\":2");
        assertThat(first.read()).isEqualTo("{\"type\":\"GameStarted\",\"tick\":0,\"fruitCount\":4,\"timeLimit\":300.0}");

        Line old = connect(server, 1, "agent");
        assertThat(old.read()).contains("\"type\":\"Welcome\"").doesNotContain("timeLimit").doesNotContain("phase");
        assertThat(old.read()).isEqualTo("{\"type\":\"GameStarted\",\"tick\":0,\"fruitCount\":4,\"timeLimit\":300.0}");
        old.send("{\"type\":\"Register\",\"seq\":2,\"name\":\"Bunny\",\"body\":" + BODY + "}");
        assertThat(old.readUntil("\"type\":\"Registered\"")).contains("\"seq\":2");

        Line viewer = connect(server, 2, "viewer");
        assertThat(viewer.read()).contains("\"type\":\"Welcome\"").contains("\"phase\":\"running\"");
        assertThat(viewer.read()).contains("\"type\":\"WorldSnapshot\"");
        assertThat(viewer.read()).contains("\"type\":\"AgentAdded\"").contains("\"name\":\"Bunny\"");
        assertThat(viewer.read()).contains("\"type\":\"AgentAdded\"").contains("\"name\":\"Guppy\"");
        assertThat(viewer.read()).isEqualTo("{\"type\":\"GameStarted\",\"tick\":0,\"seed\":11,\"fruitCount\":4,"
                + "\"timeLimit\":300.0}");
    }

    @Test
    void aMoveWithoutFromWalksFromWhereTheAgentIs() throws Exception {
        WorldServer server = started();
        Line agent = connect(server, 2, "agent");
        agent.send("{\"type\":\"Register\",\"seq\":2,\"name\":\"Guppy\",\"body\":" + BODY + "}");
        agent.readUntil("\"type\":\"Registered\"");
        agent.send("{\"type\":\"Move\",\"seq\":3,\"agent\":\"Guppy\",\"to\":{\"x\":-5,\"y\":0,\"z\":0}}");
        assertThat(agent.readUntil("\"type\":\"ActionResult\"")).contains("\"seq\":3", "\"outcome\":\"accepted\"");
    }

    @Test
    void theIssuesErrorsAreToldInTheProtocolsWords() throws Exception {
        WorldServer server = started();
        Line agent = connect(server, 2, "agent");
        agent.readUntil("\"type\":\"Welcome\"");
        agent.send("{\"type\":\"Move\",\"seq\":4,\"agent\":\"Guppy\",\"from\":{\"x\":NaN,\"y\":0,\"z\":0},"
                + "\"to\":{\"x\":1,\"y\":0,\"z\":0}}");
        assertThat(agent.readUntil("\"type\":\"Error\"")).isEqualTo("{\"type\":\"Error\",\"seq\":4,\"code\":"
                + "\"malformed_json\",\"text\":\"malformed JSON at column 55: from.x must be a finite number, was NaN"
                + " (not JSON)\"}");
        agent.send("\uFEFF{\"type\":\"EndTurn\",\"seq\":5,\"tick\":0}");
        assertThat(agent.readUntil("\"type\":\"Error\"")).contains("\"seq\":5", "it starts with a byte-order mark");
        agent.send("{\"type\":\"EndTurn\",\"seq\":9223372036854775808,\"tick\":0}");
        assertThat(agent.readUntil("\"type\":\"Error\"")).contains("\"seq\":0",
                "seq must be an integer from -9223372036854775808 to 9223372036854775807, was 9223372036854775808");
        agent.send("{\"type\":\"Hello\",\"seq\":6,\"protocolVersion\":2,\"role\":\"Viewer\",\"client\":\"c\"}");
        assertThat(agent.readUntil("\"type\":\"Error\"")).contains("\"seq\":6",
                "role must be one of 'agent', 'viewer', was the string 'Viewer'").doesNotContain("io.orchard");
        agent.send("{\"type\":\"Register\",\"seq\":7,\"name\":\"Guppy\",\"body\":" + BODY
                + ",\"model\":{\"format\":\"bundled\",\"bundled\":\"no_such_model\"}}");
        assertThat(agent.readUntil("\"type\":\"Error\"")).isEqualTo("{\"type\":\"Error\",\"seq\":7,\"code\":"
                + "\"invalid_value\",\"text\":\"model.bundled must be one of 'figure', 'bunny', was 'no_such_model'\"}");
    }

    /** A client that reads and writes raw lines. */
    private static final class Line implements AutoCloseable {
        private final Socket socket;
        private final OutputStream out;
        private final BufferedReader in;

        Line(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(10_000);
            out = socket.getOutputStream();
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        }

        void send(String line) throws IOException {
            out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            out.flush();
        }

        /** The next line that is not a tick: ticks come at any time in a realtime game. */
        String read() throws IOException {
            String line;
            do {
                line = in.readLine();
            } while (line != null && line.startsWith("{\"type\":\"Tick\""));
            return line;
        }

        String readUntil(String fragment) throws IOException {
            String line;
            while ((line = read()) != null && !line.contains(fragment)) {
                // skip the game's traffic
            }
            return line;
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
