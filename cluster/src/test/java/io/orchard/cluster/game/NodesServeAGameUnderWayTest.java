package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.cluster.ClusterNode;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.WorldServer;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.IntUnaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A game under way, played over real sockets on one world server and on three cluster nodes (in
 * this JVM, each with its own gateway on a port of its own), every client connected to a node of the
 * script's choosing: an agent that registers after the start, a late viewer, a dropped connection, a
 * stranger refused the dropped agent's name, its controller back with the resume token at another
 * node, an instruction, an agent that unregisters, the operator's pauses and resumes (with an
 * operator token, at a node that does not run the tick), turns missed at the deadline, and the end.
 * Everything that is not a turn's happens while the game is paused, so that it happens at the same
 * point of both games. The two recordings are the same file, byte for byte, and every client hears
 * the same messages.
 */
class NodesServeAGameUnderWayTest {

    private static final long SEED = 8;
    private static final double SECONDS = 4;
    private static final String OPERATOR = "conductor";
    private static final Duration DEADLINE = Duration.ofSeconds(3);

    @TempDir
    Path dir;

    @Test
    void threeNodesServeAGameUnderWayAsOneServerDoes() throws Exception {
        Path single = dir.resolve("server.ndjson");
        Map<String, List<ServerMessage>> onServer;
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(SECONDS).waitFor(2).lockstepDeadline(DEADLINE).operatorToken(OPERATOR).record(single)
                .start()) {
            onServer = new Script(node -> server.port()).play();
            server.gameOver().get(1, TimeUnit.MINUTES);
        }

        Path cluster = dir.resolve("cluster.ndjson");
        List<ClusterNode> nodes = new ArrayList<>();
        Map<String, List<ServerMessage>> onCluster;
        try {
            ClusterNode first = node(List.of()).record(cluster).start();
            nodes.add(first);
            for (int i = 0; i < 2; i++) {
                nodes.add(node(List.of("127.0.0.1:" + first.clusterPort())).start());
            }
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (first.membersUp() < 3 && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
            assertThat(first.membersUp()).as("the three nodes are up").isEqualTo(3);
            onCluster = new Script(node -> nodes.get(node).port()).play();
        } finally {
            for (int i = nodes.size() - 1; i >= 0; i--) {
                nodes.get(i).close();
            }
        }

        List<String> expected = Files.readAllLines(single);
        List<String> actual = Files.readAllLines(cluster);
        for (int i = 0; i < Math.min(expected.size(), actual.size()); i++) {
            assertThat(actual.get(i)).as("line %d of the cluster's recording", i + 1).isEqualTo(expected.get(i));
        }
        assertThat(Files.readAllBytes(cluster)).as("the cluster's recording, byte for byte")
                .isEqualTo(Files.readAllBytes(single));
        onServer.forEach((client, messages) -> {
            List<ServerMessage> got = onCluster.get(client);
            for (int i = 0; i < Math.min(messages.size(), got.size()); i++) {
                assertThat(withoutToken(got.get(i))).as("message %d that %s heard", i, client)
                        .isEqualTo(withoutToken(messages.get(i)));
            }
            assertThat(got).as("what %s heard", client).hasSameSizeAs(messages);
        });
        assertThat(String.join("\n", expected)).as("the script's events are in the game")
                .contains("\"agent\":\"Late\",", "\"reason\":\"connection closed\"", "\"code\":\"name_in_use\"",
                        "\"reason\":\"unregistered\"", "\"turn\":\"deadline\"", "\"type\":\"Instruction\"",
                        "\"command\":\"pause\"", "\"command\":\"resume\"", "\"agent\":\"Extra\",",
                        "\"type\":\"GameOver\"");
    }

    private ClusterNode.Builder node(List<String> seeds) {
        return ClusterNode.builder().port(0).clusterPort(0).seedNodes(seeds).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(SECONDS).waitFor(2).lockstepDeadline(DEADLINE).parcelSize(25).operatorToken(OPERATOR);
    }

    private static ServerMessage withoutToken(ServerMessage message) {
        return message instanceof RegisteredMessage r ? new RegisteredMessage(r.seq(), r.agent(), r.body(),
                r.position(), r.heading(), null, r.seed()) : message;
    }

    /** The script, the same for the server and the cluster; {@code port} gives node 0, 1 or 2's port. */
    private static final class Script {

        private final IntUnaryOperator port;
        private final Map<String, SocketClient> clients = new LinkedHashMap<>();
        private final Map<Forager, SocketClient> playing = new LinkedHashMap<>();
        private final List<SocketClient> closed = new ArrayList<>();
        private long seq = 10_000;

        Script(IntUnaryOperator port) {
            this.port = port;
        }

        private SocketClient connect(String name, int node, Role role, String operator) throws IOException {
            SocketClient client = SocketClient.connect(port.applyAsInt(node), role, operator);
            clients.put(name, client);
            return client;
        }

        Map<String, List<ServerMessage>> play() throws Exception {
            try {
                SocketClient first = connect("first", 0, Role.AGENT, OPERATOR);
                SocketClient second = connect("second", 1, Role.AGENT, null);
                Forager a = new Forager("ForagerA", first.heard(), 40);
                Forager b = new Forager("ForagerB", second.heard(), 30);
                first.send(a.register());
                second.send(b.register());
                first.await(RegisteredMessage.class::isInstance, "ForagerA's registration");
                second.await(RegisteredMessage.class::isInstance, "ForagerB's registration");
                first.send(a.setUp());
                second.send(b.setUp());
                playing.put(a, first);
                playing.put(b, second);
                for (long tick = 0; ; tick++) {
                    if (!perceived(tick)) {
                        break;
                    }
                    for (Map.Entry<Forager, SocketClient> agent : new ArrayList<>(playing.entrySet())) {
                        List<ClientMessage> turn = new ArrayList<>(agent.getKey().act(tick));
                        if (agent.getKey().name.equals("ForagerB") && agent.getValue() != second
                                && (tick == 40 || tick == 41)) {
                            continue; // misses its turn: the tick waits the deadline
                        }
                        if (agent.getKey() == a && (tick == 10 || tick == 30)) {
                            turn.add(turn.size() - 1, new GameControlMessage(++seq, GameCommand.PAUSE));
                        }
                        agent.getValue().send(turn);
                    }
                    if (tick == 10) {
                        accepted(first, seq);
                        firstPause(a, b, first, second, tick + 1);
                    } else if (tick == 30) {
                        accepted(first, seq);
                        secondPause(first, tick + 1);
                    }
                }
                for (SocketClient client : clients.values()) {
                    if (!closed.contains(client)) {
                        client.await(GameOverMessage.class::isInstance, "the end of the game");
                    }
                }
                Map<String, List<ServerMessage>> heard = new LinkedHashMap<>();
                clients.forEach((name, client) -> heard.put(name, client.heard().all()));
                return heard;
            } finally {
                for (SocketClient client : clients.values()) {
                    client.close();
                }
            }
        }

        /** Waits for every playing agent's perception of {@code tick}; false when the game ended instead. */
        private boolean perceived(long tick) throws InterruptedException {
            for (Map.Entry<Forager, SocketClient> agent : playing.entrySet()) {
                String name = agent.getKey().name;
                ServerMessage got = agent.getValue().await(m -> m instanceof PerceptionMessage p && p.tick() == tick
                        && p.agent().equals(name) || m instanceof GameOverMessage, name + "'s perception of " + tick);
                if (got instanceof GameOverMessage) {
                    return false;
                }
            }
            return true;
        }

        /** While the game is paused after {@code tick} - 1: a late agent and viewer, a drop and a return. */
        private void firstPause(Forager a, Forager b, SocketClient first, SocketClient second, long tick)
                throws Exception {
            SocketClient late = connect("late", 2, Role.AGENT, null);
            Forager lateComer = new Forager("Late", late.heard(), 30);
            late.send(lateComer.register());
            late.await(RegisteredMessage.class::isInstance, "the late agent's registration");
            setUp(lateComer, late, tick);

            SocketClient viewer = connect("viewer", 1, Role.VIEWER, null);
            viewer.await(GameStartedMessage.class::isInstance, "the late viewer's catching up");
            assertThat(viewer.heard().all().get(0)).as("what a late viewer hears first")
                    .isInstanceOf(WorldSnapshotMessage.class);
            viewer.send(new InstructionMessage(++seq, "ForagerA", "go north", "teacher"));
            first.await(InstructionMessage.class::isInstance, "the instruction");
            viewer.send(new InstructionMessage(++seq, "Nobody", "hello", "teacher"));
            long nobody = seq;
            viewer.await(m -> m instanceof ErrorMessage e && e.seq() == nobody, "the unknown agent's error");

            second.close();
            closed.add(second);
            playing.remove(b);
            viewer.await(m -> m instanceof AgentRemovedMessage r && r.agent().equals("ForagerB"), "ForagerB leaving");
            SocketClient stranger = connect("stranger", 0, Role.AGENT, null);
            stranger.send(new Forager("ForagerB", stranger.heard(), 20).register());
            stranger.await(ErrorMessage.class::isInstance, "the stranger's refusal");
            stranger.close();
            closed.add(stranger);

            SocketClient back = connect("back", 2, Role.AGENT, null);
            Forager bAgain = new Forager("ForagerB", back.heard(), 30);
            String token = second.heard().all().stream().filter(RegisteredMessage.class::isInstance)
                    .map(m -> ((RegisteredMessage) m).resumeToken()).findFirst().orElseThrow();
            back.send(bAgain.resume(token));
            back.await(RegisteredMessage.class::isInstance, "ForagerB back");
            setUp(bAgain, back, tick);

            first.send(new GameControlMessage(++seq, GameCommand.RESUME));
            accepted(first, seq);
            playing.put(lateComer, late);
            playing.put(bAgain, back);
        }

        /** While the game is paused again: an agent unregisters, another comes, a viewer, a move refused. */
        private void secondPause(SocketClient first, long tick) throws Exception {
            Forager lateComer = playing.keySet().stream().filter(f -> f.name.equals("Late")).findFirst().orElseThrow();
            SocketClient late = playing.remove(lateComer);
            late.send(new UnregisterMessage(++seq, "Late"));
            accepted(late, seq);
            clients.get("viewer").await(m -> m instanceof AgentRemovedMessage r && r.agent().equals("Late"),
                    "Late leaving");

            SocketClient extra = connect("extra", 0, Role.AGENT, null);
            Forager extraOne = new Forager("Extra", extra.heard(), 20);
            extra.send(extraOne.register());
            extra.await(RegisteredMessage.class::isInstance, "the extra agent's registration");
            setUp(extraOne, extra, tick);

            SocketClient pausedViewer = connect("pausedViewer", 2, Role.VIEWER, null);
            pausedViewer.await(GameStartedMessage.class::isInstance, "the second viewer's catching up");

            first.send(new MoveMessage(++seq, "ForagerA", null, Vec3.ground(1, 1)));
            long move = seq;
            first.await(m -> m instanceof ActionResultMessage r && r.seq() == move, "the refused move");
            first.send(new GameControlMessage(++seq, GameCommand.RESUME));
            accepted(first, seq);
            playing.put(extraOne, extra);
        }

        private void setUp(Forager agent, SocketClient client, long tick) throws Exception {
            List<ClientMessage> setUp = agent.setUpIn(tick);
            client.send(setUp);
            long request = setUp.stream().filter(PerceptionRequestMessage.class::isInstance).findFirst()
                    .orElseThrow().seq();
            client.await(m -> m instanceof ActionResultMessage r && r.seq() == request, agent.name + "'s setup");
        }

        private static void accepted(SocketClient client, long seq) throws InterruptedException {
            ServerMessage result = client.await(m -> m instanceof ActionResultMessage r && r.seq() == seq,
                    "the answer to " + seq);
            assertThat(((ActionResultMessage) result).outcome()).as("the answer to " + seq)
                    .isEqualTo(Outcome.ACCEPTED);
        }
    }
}
