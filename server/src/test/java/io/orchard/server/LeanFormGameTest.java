package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.TestWorlds;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same scripted game played three times on a lockstep server of one seed, by a version 1
 * client, a version 2 client that asks for no form, and one that reads the lean form: the first
 * two get the very same lines, and the lean client gets those lines with each perception's three
 * in one {@code LeanPerception} line and without the results of its accepted moves, and plays the
 * same game from them.
 */
class LeanFormGameTest {

    private static final String BODY = "{\"radius\":0.5,\"height\":1.2,\"maxSpeed\":10,\"gripper\":{\"part\":\"hands\","
            + "\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},\"sight\":{\"range\":40,\"fieldOfView\":3.14}}";
    private static final int LAST_TICK = 24;

    private final MessageCodec codec = new MessageCodec();

    @TempDir
    Path dir;

    @Test
    void versionOneAndVersionTwoWithoutFormsGetTheSameLinesAndTheLeanFormTheSameGameInFewer() throws Exception {
        List<String> v1 = play("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"s\"}");
        List<String> v2 = play("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,\"role\":\"agent\",\"client\":\"s\"}");
        List<String> lean = play("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,\"role\":\"agent\",\"client\":\"s\","
                + "\"reads\":[\"LeanPerception\"]}");

        assertThat(masked(v1)).containsExactlyElementsOf(masked(v2));
        List<String> types = v2.stream().map(line -> type(codec.decodeServer(line))).toList();
        assertThat(types).contains("Perception", "LandmarkPerception", "CastlePerception", "FruitEaten")
                .doesNotContain("LeanPerception");
        List<ServerMessage> ordinary = v2.stream().map(codec::decodeServer).toList();
        assertThat(ordinary).anyMatch(m -> m instanceof ActionResultMessage r && r.action().equals("Move")
                && r.outcome() == Outcome.ACCEPTED).anyMatch(m -> m instanceof ActionResultMessage r
                && r.action().equals("Move") && r.outcome() == Outcome.REJECTED)
                .anyMatch(m -> m instanceof GraspResultMessage g && g.success());

        assertThat(masked(lean)).containsExactlyElementsOf(masked(leanFormOf(v2)));
        assertThat(lean).anyMatch(line -> line.startsWith("{\"type\":\"LeanPerception\""))
                .noneMatch(line -> line.startsWith("{\"type\":\"Perception\""))
                .noneMatch(line -> line.contains("\"action\":\"Move\",\"outcome\":\"accepted\""));
    }

    /** The lean client's perceptions are the ordinary ones, at the precision the server rounds to. */
    @Test
    void aLeanPerceptionRebuildsTheOrdinaryPerceptionOfTheSameTick() throws Exception {
        List<ServerMessage> ordinary = play("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,\"role\":\"agent\","
                + "\"client\":\"s\"}").stream().map(codec::decodeServer).toList();
        List<LeanPerceptionMessage> lean = play("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,\"role\":\"agent\","
                + "\"client\":\"s\",\"reads\":[\"LeanPerception\",\"AcceptedMoves\"]}").stream().map(codec::decodeServer)
                .filter(LeanPerceptionMessage.class::isInstance).map(LeanPerceptionMessage.class::cast).toList();
        List<PerceptionMessage> seen = ordinary.stream().filter(PerceptionMessage.class::isInstance)
                .map(PerceptionMessage.class::cast).toList();
        assertThat(lean).hasSize(seen.size()).hasSizeGreaterThan(LAST_TICK - 3);
        for (int i = 0; i < seen.size(); i++) {
            assertThat(lean.get(i).toPerception()).isEqualTo(seen.get(i));
        }
        assertThat(lean).anyMatch(l -> !l.toPerception().fruit().isEmpty() && !l.toPerception().objects().isEmpty());
    }

    /** The ordinary lines as a lean client should get them: a perception's three as one line, no accepted move. */
    private List<String> leanFormOf(List<String> lines) {
        List<String> lean = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            ServerMessage message = codec.decodeServer(lines.get(i));
            if (message instanceof PerceptionMessage seen) {
                lean.add(codec.encode(LeanPerceptionMessage.of(seen,
                        (LandmarkPerceptionMessage) codec.decodeServer(lines.get(i + 1)),
                        (CastlePerceptionMessage) codec.decodeServer(lines.get(i + 2)))));
                i += 2;
            } else if (!(message instanceof ActionResultMessage r && r.action().equals("Move")
                    && r.outcome() == Outcome.ACCEPTED)) {
                lean.add(lines.get(i));
            }
        }
        return lean;
    }

    /** The lines with what differs from game to game, or from version to version by design, blanked. */
    private static List<String> masked(List<String> lines) {
        return lines.stream()
                .map(line -> line.replaceFirst("^(\\{\"type\":\"Welcome\",\"seq\":1,\"protocolVersion\":)\\d+", "$1_")
                        .replaceFirst("(\"type\":\"Welcome\".*),\"timeLimit\":[^,}]+,\"phase\":\"[a-z]+\"", "$1")
                        .replaceFirst("(\"type\":\"Registered\".*),\"resumeToken\":\"[0-9a-f]+\"", "$1")
                        .replaceFirst("(\"type\":\"Registered\".*),\"seed\":-?\\d+", "$1"))
                .toList();
    }

    private static String type(ServerMessage message) {
        return io.orchard.protocol.MessageTypes.nameOf(message.getClass());
    }

    /**
     * Plays the script as a client that says {@code hello} and returns every line it read up to the
     * start of the last tick: it faces the tomato F1 south of it, walks to it in two moves, sends one
     * move from the wrong place and one through tree T1, and picks the tomato up.
     */
    private List<String> play(String hello) throws Exception {
        Path scenario = dir.resolve("small.json");
        ScenarioFile.write(TestWorlds.small().toScenario(), scenario);
        try (WorldServer server = WorldServer.builder().port(0).seed(11).scenario(scenario).clock(ClockMode.LOCKSTEP)
                .lockstepDeadline(Duration.ofSeconds(30)).timeLimit(60)
                .placement((name, radius) -> Map.of("Guppy", Vec3.ground(0, 0)).get(name)).start();
             Socket socket = new Socket("127.0.0.1", server.port())) {
            socket.setSoTimeout(30_000);
            OutputStream out = socket.getOutputStream();
            BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
            List<String> lines = new ArrayList<>();
            Script script = new Script(out);
            script.send(hello);
            script.send("{\"type\":\"Register\",\"seq\":2,\"name\":\"Guppy\",\"body\":" + BODY + "}");
            script.setUp();
            String line;
            while ((line = in.readLine()) != null) {
                lines.add(line);
                ServerMessage message = codec.decodeServer(line);
                if (message instanceof TickMessage tick) {
                    if (tick.tick() == LAST_TICK) {
                        return lines;
                    }
                    script.tick(tick.tick());
                } else if (message instanceof PerceptionMessage seen) {
                    script.perceived(seen.tick(), seen.position());
                } else if (message instanceof LeanPerceptionMessage seen) {
                    script.perceived(seen.tick(), seen.toPerception().position());
                }
            }
            throw new AssertionError("the server closed the connection after " + lines);
        }
    }

    /** What the agent does, by tick: the same whatever form it reads, from the position it perceives. */
    private static final class Script {
        private final OutputStream out;
        private long seq = 2;
        private long pending = -1;

        Script(OutputStream out) {
            this.out = out;
        }

        /** The setup turn: a lockstep game starts once it is over. */
        void setUp() throws IOException {
            send("{\"type\":\"EndTurn\",\"seq\":" + ++seq + ",\"tick\":0}");
        }

        void tick(long tick) throws IOException {
            pending = tick;
            send("{\"type\":\"PerceptionRequest\",\"seq\":" + ++seq + ",\"agent\":\"Guppy\",\"every\":0}");
            if (tick == 0) {
                send("{\"type\":\"EndTurn\",\"seq\":" + ++seq + ",\"tick\":0}");
                pending = -1;
            }
        }

        void perceived(long tick, Vec3 at) throws IOException {
            if (tick != pending) {
                return;
            }
            String from = "{\"x\":" + at.x() + ",\"y\":0,\"z\":" + at.z() + "}";
            switch ((int) tick) {
                case 1 -> send("{\"type\":\"SetRotation\",\"seq\":" + ++seq + ",\"agent\":\"Guppy\",\"rotation\":"
                        + "{\"axis\":{\"x\":0,\"y\":1,\"z\":0},\"angle\":3.14159}}");
                case 2 -> move(from, "{\"x\":0,\"y\":0,\"z\":2.5}");
                case 3 -> move("{\"x\":30,\"y\":0,\"z\":30}", "{\"x\":31,\"y\":0,\"z\":30}");
                case 10 -> move(from, "{\"x\":0,\"y\":0,\"z\":4.2}");
                case 16 -> send("{\"type\":\"GraspRequest\",\"seq\":" + ++seq + ",\"agent\":\"Guppy\",\"fruit\":\"F1\"}");
                case 18 -> move(from, "{\"x\":0,\"y\":0,\"z\":-20}");
                default -> { }
            }
            send("{\"type\":\"EndTurn\",\"seq\":" + ++seq + ",\"tick\":" + tick + "}");
            pending = -1;
        }

        private void move(String from, String to) throws IOException {
            send("{\"type\":\"Move\",\"seq\":" + ++seq + ",\"agent\":\"Guppy\",\"from\":" + from + ",\"to\":" + to + "}");
        }

        void send(String line) throws IOException {
            out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            out.flush();
        }
    }
}
