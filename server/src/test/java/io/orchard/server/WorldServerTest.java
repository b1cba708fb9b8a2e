package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.net.NetLimits;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The server on a real port, spoken to over real sockets. */
class WorldServerTest {

    static final Body BODY = new Body(0.5, 1.2, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(40, Math.PI));

    @TempDir
    Path dir;

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = open.size() - 1; i >= 0; i--) {
            open.get(i).close();
        }
    }

    private WorldServer.Builder server() throws IOException {
        Path scenario = dir.resolve("small.json");
        ScenarioFile.write(io.orchard.server.sim.TestWorlds.small().toScenario(), scenario);
        return WorldServer.builder().port(0).seed(11).scenario(scenario)
                .placement((name, radius) -> Map.of("Guppy", Vec3.ground(0, 0), "Bunny", Vec3.ground(-20, -15)).get(name));
    }

    private WorldServer started(WorldServer.Builder builder) throws IOException {
        WorldServer server = builder.start();
        open.add(server);
        return server;
    }

    /** A client whose every message lands in a queue the test reads. */
    private final class Client {
        final BlockingQueue<ServerMessage> inbox = new LinkedBlockingQueue<>();
        /** Every message heard, in order, whether awaited or not. */
        final List<ServerMessage> seen = new java.util.concurrent.CopyOnWriteArrayList<>();
        final ProtocolConnection connection;

        Client(int port, Role role) throws IOException {
            connection = ProtocolConnection.connect("127.0.0.1", port, role, "test", message -> {
                seen.add(message);
                inbox.add(message);
            });
            open.add(connection);
        }

        Reply ask(java.util.function.LongFunction<? extends io.orchard.protocol.message.ClientMessage> message)
                throws Exception {
            return connection.request(message).get(10, TimeUnit.SECONDS);
        }

        <T extends ServerMessage> T await(Class<T> type, Predicate<T> which) throws InterruptedException {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (System.nanoTime() < end) {
                ServerMessage message = inbox.poll(100, TimeUnit.MILLISECONDS);
                if (type.isInstance(message) && which.test(type.cast(message))) {
                    return type.cast(message);
                }
            }
            throw new AssertionError("no " + type.getSimpleName() + " arrived");
        }
    }

    @Test
    void anAgentRegistersMovesIsBlockedPerceivesAndGrasps() throws Exception {
        WorldServer server = started(server().clock(ClockMode.REALTIME).tickRate(50));
        Client viewer = new Client(server.port(), Role.VIEWER);
        assertThat(viewer.await(WorldSnapshotMessage.class, s -> true).fruit()).hasSize(4);
        Client agent = new Client(server.port(), Role.AGENT);
        RegisteredMessage registered = (RegisteredMessage) agent.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, null));
        assertThat(registered.position()).isEqualTo(Vec3.ground(0, 0));
        assertThat(registered.seed()).as("a version 2 client gets its agent's seed").isNotNull();
        assertThat(viewer.await(AgentAddedMessage.class, a -> true).agent().name()).isEqualTo("Guppy");

        ActionResultMessage blocked = (ActionResultMessage) agent.ask(seq ->
                new MoveMessage(seq, "Guppy", Vec3.ZERO, Vec3.ground(0, -20)));
        assertThat(blocked.outcome()).isEqualTo(Outcome.REJECTED);
        assertThat(blocked.reason()).isEqualTo("path crosses tree T1");

        agent.ask(seq -> new SetRotationMessage(seq, "Guppy", Rotation.heading(Math.PI)));
        agent.ask(seq -> new PerceptionRequestMessage(seq, "Guppy", 0));
        PerceptionMessage perception = agent.await(PerceptionMessage.class, p -> true);
        assertThat(perception.fruit()).extracting(f -> f.id()).contains("F1");

        ActionResultMessage moved = (ActionResultMessage) agent.ask(seq ->
                new MoveMessage(seq, "Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
        assertThat(moved.outcome()).isEqualTo(Outcome.ACCEPTED);
        Thread.sleep((long) (moved.duration() * 1000) + 200);
        GraspResultMessage grasp = (GraspResultMessage) agent.ask(seq -> new GraspRequestMessage(seq, "Guppy", "F1"));
        assertThat(grasp.success()).as(grasp.reason()).isTrue();
        assertThat(server.status()).contains("fruit left 3");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        malformed JSON        | {"type":"Move",                            | malformed_json
        unknown type          | {"type":"Fly","seq":4}                     | unknown_type
        missing field         | {"type":"Unregister","seq":4}              | missing_field
        not a number          | {"type":"EndTurn","seq":4,"tick":"soon"}   | invalid_value
        infinity              | {"type":"EndTurn","seq":4,"tick":1e999}    | invalid_value
        server-only message   | {"type":"Tick","tick":1,"time":0}          | wrong_direction
        """)
    void badLinesAreAnsweredWithAnErrorAndTheConnectionStaysOpen(String name, String line, String code)
            throws Exception {
        WorldServer server = started(server());
        try (RawClient raw = new RawClient(server.port())) {
            raw.send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"raw\"}");
            assertThat(raw.read()).contains("\"type\":\"Welcome\"");
            raw.send(line);
            String error = raw.read();
            assertThat(error).contains("\"type\":\"Error\"").contains("\"code\":\"" + code + "\"");
            raw.send("{\"type\":\"Register\",\"seq\":9,\"name\":\"Guppy\",\"body\":" + bodyJson() + "}");
            assertThat(raw.readUntil("Registered")).contains("\"seq\":9")
                    .as("a version 1 client is not sent the agent's seed").doesNotContain("\"seed\"");
        }
    }

    @Test
    void messagesBeforeTheHandshakeAreRefused() throws Exception {
        WorldServer server = started(server());
        try (RawClient raw = new RawClient(server.port())) {
            raw.send("{\"type\":\"Unregister\",\"seq\":3,\"agent\":\"Guppy\"}");
            assertThat(raw.read()).contains("handshake_required").contains("\"seq\":3");
        }
    }

    @Test
    void aWrongProtocolVersionIsRefusedAndClosed() throws Exception {
        WorldServer server = started(server());
        try (RawClient raw = new RawClient(server.port())) {
            raw.send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":99,\"role\":\"agent\",\"client\":\"raw\"}");
            assertThat(raw.read()).contains("version_mismatch").contains("99");
            assertThat(raw.read()).isNull();
        }
    }

    @Test
    void anOversizedLineClosesTheConnectionAfterAnError() throws Exception {
        WorldServer server = started(server());
        try (RawClient raw = new RawClient(server.port())) {
            raw.send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"raw\"}");
            raw.read();
            raw.send("{\"type\":\"Say\",\"seq\":2,\"agent\":\"Guppy\",\"text\":\"" + "x".repeat(MessageCodec.MAX_LINE_BYTES)
                    + "\"}");
            assertThat(raw.read()).contains("line_too_long");
            assertThat(raw.read()).isNull();
        }
    }

    @Test
    void aFloodIsCutOff() throws Exception {
        WorldServer server = started(server().limits(new NetLimits(50, 100, Duration.ofSeconds(60),
                Duration.ofSeconds(5), 1 << 20)));
        try (RawClient raw = new RawClient(server.port())) {
            StringBuilder burst = new StringBuilder();
            for (int i = 0; i < 500; i++) {
                burst.append("{\"type\":\"EndTurn\",\"seq\":").append(i).append(",\"tick\":0}\n");
            }
            raw.out.write(burst.toString().getBytes(StandardCharsets.UTF_8));
            raw.out.flush();
            assertThat(raw.readUntil("rate_limited")).contains("rate_limited");
            assertThat(raw.readUntil("never")).isNull();
        }
    }

    @Test
    void aTokenIsRequiredWhenSet() throws Exception {
        WorldServer server = started(server().token("s3cret"));
        assertThatThrownBy(() -> new Client(server.port(), Role.AGENT)).hasMessageContaining("unauthorized");
        ProtocolConnection ok = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "test", "s3cret",
                m -> { });
        open.add(ok);
        assertThat(ok.welcome().role()).isEqualTo(Role.AGENT);
    }

    @Test
    void aDroppedAgentIsRemovedAndAnnounced() throws Exception {
        WorldServer server = started(server());
        Client viewer = new Client(server.port(), Role.VIEWER);
        Client agent = new Client(server.port(), Role.AGENT);
        agent.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, null));
        agent.connection.close();
        assertThat(viewer.await(AgentRemovedMessage.class, r -> true).agent()).isEqualTo("Guppy");
        assertThat(server.status()).contains("agents []");
    }

    /**
     * A viewer that never reads while 24 agents with models of 1 MiB come and go: it is cut off with
     * its {@code slow_consumer} error, having been sent a bounded part of what it did not read, and
     * the agent in the same game gets every answer and hears every tick, in order, before and after.
     */
    @Test
    void aViewerThatStopsReadingIsCutOffWithoutStallingTheGame() throws Exception {
        WorldServer server = started(server().limits(new NetLimits(2_000, 4_000, Duration.ofSeconds(60),
                Duration.ofMillis(300), 4L << 20)));
        Socket stalled = new Socket();
        stalled.setReceiveBufferSize(4096);
        stalled.connect(new java.net.InetSocketAddress("127.0.0.1", server.port()));
        open.add(stalled);
        stalled.getOutputStream().write(("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"viewer\","
                + "\"client\":\"stalled\"}\n").getBytes(StandardCharsets.UTF_8));
        Client agent = new Client(server.port(), Role.AGENT);
        ModelSpec model = ModelSpec.of(ModelFormat.GLB, new byte[1 << 20]);
        for (int i = 0; i < 24; i++) {
            assertThat(agent.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, model))).isInstanceOf(RegisteredMessage.class);
            ActionResultMessage unregistered = (ActionResultMessage) agent.ask(seq -> new UnregisterMessage(seq, "Guppy"));
            assertThat(unregistered.outcome()).isEqualTo(Outcome.ACCEPTED);
        }
        // The game goes on: the agent hears ticks after the registrations too, and missed none.
        awaitMoreTicks(agent, 10);
        assertHeardEveryTick(agent);
        // The stalled viewer's connection was closed by the server, with its error after what its
        // socket held: reading drains it to the end.
        stalled.setSoTimeout(30_000);
        BufferedReader in = new BufferedReader(new InputStreamReader(stalled.getInputStream(), StandardCharsets.UTF_8));
        String lastLine = null;
        long total = 0;
        try {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                lastLine = line;
                total += line.length() + 1;
            }
        } catch (java.net.SocketException reset) {
            // closed: what was read is what counts
        }
        assertThat(lastLine).contains("\"code\":\"slow_consumer\"");
        assertThat(total).as("bytes sent to the viewer that did not read").isLessThan(24L << 21);
    }

    /** Waits until the client hears the tick {@code more} after the latest it has heard. */
    private static void awaitMoreTicks(Client client, int more) throws InterruptedException {
        long latest = client.seen.stream().filter(TickMessage.class::isInstance).mapToLong(m -> ((TickMessage) m).tick())
                .max().orElse(0);
        client.await(TickMessage.class, t -> t.tick() >= latest + more);
    }

    /** The client heard more than ten ticks, each the one after the tick before: none was skipped. */
    private static void assertHeardEveryTick(Client client) {
        List<Long> ticks = new ArrayList<>();
        for (ServerMessage message : client.seen) {
            if (message instanceof TickMessage tick) {
                ticks.add(tick.tick());
            }
        }
        assertThat(ticks.size()).as("ticks heard").isGreaterThan(10);
        for (int i = 1; i < ticks.size(); i++) {
            assertThat(ticks.get(i)).as("the tick after " + ticks.get(i - 1)).isEqualTo(ticks.get(i - 1) + 1);
        }
    }

    @Test
    void anAgentThatStopsReadingIsCutOffWithoutStallingTheGame() throws Exception {
        WorldServer server = started(server().limits(new NetLimits(100_000, 100_000, Duration.ofSeconds(60),
                Duration.ofMillis(500), 4L << 20)));
        Client viewer = new Client(server.port(), Role.VIEWER);
        Socket stalled = new Socket();
        stalled.setReceiveBufferSize(4096);
        stalled.connect(new java.net.InetSocketAddress("127.0.0.1", server.port()));
        open.add(stalled);
        stalled.getOutputStream().write(("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\","
                + "\"client\":\"stalled\"}\n{\"type\":\"Register\",\"seq\":2,\"name\":\"Stall\",\"body\":" + bodyJson()
                + "}\n").getBytes(StandardCharsets.UTF_8));
        viewer.await(AgentAddedMessage.class, a -> a.agent().name().equals("Stall"));
        Client talker = new Client(server.port(), Role.AGENT);
        talker.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, null));
        String words = "blah ".repeat(199);
        long ticksBefore = server.tickStats().ticks();
        Thread flood = new Thread(() -> {
            try {
                // Instructions go to the stalled agent's connection alone: about 20 MB a second of them.
                for (int i = 0; i < 60_000 && !Thread.currentThread().isInterrupted(); i++) {
                    talker.connection.send(seq -> new io.orchard.protocol.message.InstructionMessage(seq, "Stall", words,
                            "Guppy"));
                    if (i % 200 == 199) {
                        Thread.sleep(10);
                    }
                }
            } catch (IOException | InterruptedException e) {
                // the test is over
            }
        }, "flood");
        flood.start();
        try {
            AgentRemovedMessage removed = viewer.await(AgentRemovedMessage.class, r -> r.agent().equals("Stall"));
            assertThat(removed.reason()).isEqualTo("connection closed");
            assertThat(server.tickStats().ticks()).as("ticks went on").isGreaterThan(ticksBefore);
            assertThat(server.status()).contains("agents [Guppy]");
            awaitMoreTicks(talker, 10);
            assertHeardEveryTick(talker);
        } finally {
            flood.interrupt();
            talker.connection.close(); // a send blocked on a full socket ends with the connection
            flood.join(10_000);
        }
    }

    @Test
    void aViewerThatReconnectsGetsAFullAndCorrectSnapshot() throws Exception {
        WorldServer server = started(server().tickRate(50));
        Client first = new Client(server.port(), Role.VIEWER);
        first.await(WorldSnapshotMessage.class, s -> true);
        Client agent = new Client(server.port(), Role.AGENT);
        agent.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, null));
        agent.ask(seq -> new SetRotationMessage(seq, "Guppy", Rotation.heading(Math.PI)));
        ActionResultMessage walk = (ActionResultMessage) agent.ask(seq -> new MoveMessage(seq, "Guppy", Vec3.ZERO,
                Vec3.ground(0, 4)));
        Thread.sleep((long) (walk.duration() * 1000) + 200);
        GraspResultMessage grasp = (GraspResultMessage) agent.ask(seq -> new GraspRequestMessage(seq, "Guppy", "F1"));
        assertThat(grasp.success()).as(grasp.reason()).isTrue();
        first.connection.close();
        ActionResultMessage away = (ActionResultMessage) agent.ask(seq -> new MoveMessage(seq, "Guppy",
                Vec3.ground(0, 4), Vec3.ground(-3, 4)));
        Thread.sleep((long) (away.duration() * 1000) + 200);

        Client second = new Client(server.port(), Role.VIEWER);
        WorldSnapshotMessage snapshot = second.await(WorldSnapshotMessage.class, s -> true);
        AgentAddedMessage guppy = second.await(AgentAddedMessage.class, a -> true);
        io.orchard.server.sim.Checkpoint truth = io.orchard.server.sim.CheckpointFile.read(
                server.checkpoint(dir.resolve("truth.json")).get(10, TimeUnit.SECONDS));
        assertThat(snapshot.fruit()).isEqualTo(truth.world().fruit());
        assertThat(snapshot.fruit()).extracting(f -> f.id()).containsExactly("F2", "F4", "F5");
        assertThat(snapshot.obstacles()).hasSize(2);
        assertThat(snapshot.scores()).isEqualTo(truth.scores()).containsExactly(new io.orchard.protocol.value.Score(
                "Guppy", 1, 1));
        assertThat(guppy.agent().position()).isEqualTo(truth.agents().get(0).position());
        assertThat(guppy.agent().position().x()).isCloseTo(-3, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(guppy.agent().heading()).isEqualTo(Math.PI);
    }

    @Test
    void aSavedGameContinuesInANewServerAndItsAgentComesBackWithItsToken() throws Exception {
        Path checkpoint = dir.resolve("game.checkpoint.json");
        String token;
        try (WorldServer first = server().tickRate(50).checkpoint(checkpoint, null).start()) {
            Client agent = new Client(first.port(), Role.AGENT);
            RegisteredMessage registered = (RegisteredMessage) agent.ask(seq -> new RegisterMessage(seq, "Guppy", BODY,
                    null));
            token = registered.resumeToken();
            agent.ask(seq -> new SetRotationMessage(seq, "Guppy", Rotation.heading(Math.PI)));
            ActionResultMessage walk = (ActionResultMessage) agent.ask(seq -> new MoveMessage(seq, "Guppy", Vec3.ZERO,
                    Vec3.ground(0, 4)));
            Thread.sleep((long) (walk.duration() * 1000) + 200);
            assertThat(((GraspResultMessage) agent.ask(seq -> new GraspRequestMessage(seq, "Guppy", "F1"))).success())
                    .isTrue();
            assertThat(first.checkpoint().get(10, TimeUnit.SECONDS)).isEqualTo(checkpoint);
        }
        WorldServer second = started(WorldServer.builder().port(0).resume(checkpoint));
        assertThat(second.status()).contains("paused", "waiting to be resumed [Guppy]", "fruit left 3");
        Client intruder = new Client(second.port(), Role.AGENT);
        Reply refused = intruder.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, null));
        assertThat(((ErrorMessage) refused).code()).isEqualTo(io.orchard.protocol.message.ErrorCode.NAME_IN_USE);
        Client agent = new Client(second.port(), Role.AGENT);
        RegisteredMessage back = (RegisteredMessage) agent.ask(seq -> new RegisterMessage(seq, "Guppy", BODY, null,
                token));
        assertThat(back.position().z()).isCloseTo(4, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(back.heading()).isEqualTo(Math.PI);
        GraspResultMessage again = (GraspResultMessage) agent.ask(seq -> new GraspRequestMessage(seq, "Guppy", "F1"));
        assertThat(again.success()).isFalse();
        assertThat(second.status()).contains("running", "scores Guppy 1 point (1 fruit)").doesNotContain("waiting to be resumed");
    }

    @Test
    void theServerListensOnlyWhereItIsToldToAndOnLoopbackByDefault() throws Exception {
        WorldServer byDefault = started(server());
        assertThat(byDefault.address().getAddress().isLoopbackAddress()).isTrue();
        assertThat(byDefault.address().getAddress().getHostAddress()).isEqualTo("127.0.0.1");
        WorldServer elsewhere = started(server().bind("127.0.0.2"));
        assertThat(elsewhere.address().getAddress().getHostAddress()).isEqualTo("127.0.0.2");
        assertThatThrownBy(() -> new Socket("127.0.0.1", elsewhere.port()).close())
                .isInstanceOf(java.net.ConnectException.class);
        ProtocolConnection there = ProtocolConnection.connect("127.0.0.2", elsewhere.port(), Role.VIEWER, "test",
                m -> { });
        open.add(there);
        assertThat(there.welcome().role()).isEqualTo(Role.VIEWER);
    }

    @Test
    void aLineLeftUnfinishedClosesTheConnection() throws Exception {
        WorldServer server = started(server().limits(NetLimits.DEFAULT.withLineDeadline(Duration.ofMillis(300))));
        try (RawClient raw = new RawClient(server.port())) {
            raw.send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"raw\"}");
            assertThat(raw.read()).contains("Welcome");
            raw.out.write("{\"type\":\"EndTurn\",\"seq\":".getBytes(StandardCharsets.UTF_8));
            raw.out.flush();
            assertThat(raw.readUntil("\"code\"")).contains("\"code\":\"idle\"").contains("unfinished");
            assertThat(raw.read()).isNull();
        }
    }

    @Test
    void connectionsBeyondTheCapAreRefused() throws Exception {
        WorldServer server = started(server().limits(NetLimits.DEFAULT.withMaxConnections(2)));
        new Client(server.port(), Role.VIEWER);
        new Client(server.port(), Role.AGENT);
        try (RawClient raw = new RawClient(server.port())) {
            assertThat(raw.read()).contains("too_many_agents").contains("at most 2 connections");
            assertThat(raw.read()).isNull();
        }
    }

    @Test
    void aConnectionThatClosesWhileRegisteringLeavesNoAgentBehind() throws Exception {
        WorldServer server = started(server());
        Client viewer = new Client(server.port(), Role.VIEWER);
        try (RawClient raw = new RawClient(server.port())) {
            raw.send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"raw\"}"
                    + "\n{\"type\":\"Register\",\"seq\":2,\"name\":\"Guppy\",\"body\":" + bodyJson() + "}");
        }
        assertThat(viewer.await(AgentRemovedMessage.class, r -> r.agent().equals("Guppy")).reason())
                .isEqualTo("connection closed");
        assertThat(server.status()).contains("agents []", "scores Guppy 0 points (0 fruit)");
    }

    @Test
    void theSameSeedAndActionsInLockstepGiveByteIdenticalRecordings() throws Exception {
        Path first = dir.resolve("first.ndjson");
        Path second = dir.resolve("second.ndjson");
        playScriptedGame(first);
        playScriptedGame(second);
        assertThat(Files.size(first)).isGreaterThan(1000);
        assertThat(Files.readAllBytes(second)).isEqualTo(Files.readAllBytes(first));
        assertThat(Files.readAllLines(first)).anyMatch(l -> l.contains("\"type\":\"Perception\""))
                .anyMatch(l -> l.contains("\"dir\":\"in\""));
    }

    private void playScriptedGame(Path recording) throws Exception {
        try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(2)
                .record(recording).start()) {
            BlockingQueue<ServerMessage> inbox = new LinkedBlockingQueue<>();
            try (ProtocolConnection agent = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "script",
                    inbox::add)) {
                RegisteredMessage me = (RegisteredMessage) agent.request(seq -> new RegisterMessage(seq, "Guppy", BODY,
                        null)).get(10, TimeUnit.SECONDS);
                agent.send(seq -> new EndTurnMessage(seq, 0)); // the setup turn: the game starts
                Vec3 position = me.position();
                while (!server.gameOver().isDone()) {
                    ServerMessage message = inbox.poll(10, TimeUnit.SECONDS);
                    if (message instanceof TickMessage tick) {
                        long n = tick.tick();
                        agent.send(seq -> new PerceptionRequestMessage(seq, "Guppy", 0));
                        if (n % 10 == 0) {
                            Vec3 from = position;
                            Vec3 to = Vec3.ground(from.x() + 1, from.z());
                            agent.send(seq -> new MoveMessage(seq, "Guppy", from, to));
                        }
                        agent.send(seq -> new EndTurnMessage(seq, n));
                    } else if (message instanceof ActionResultMessage result && result.position() != null
                            && result.outcome() != Outcome.REJECTED) {
                        position = result.position();
                    } else if (message instanceof io.orchard.protocol.message.GameOverMessage) {
                        break;
                    } else if (message == null) {
                        throw new AssertionError("the server went quiet");
                    }
                }
            }
        }
    }

    private static String bodyJson() {
        return "{\"radius\":0.5,\"height\":1.2,\"maxSpeed\":10,\"gripper\":{\"part\":\"hands\",\"reach\":0.6,"
                + "\"minHeight\":0,\"maxHeight\":1.5},\"sight\":{\"range\":30,\"fieldOfView\":3.14}}";
    }

    /** A client that speaks raw lines, to send what a well-behaved client never would. */
    private static final class RawClient implements AutoCloseable {
        final Socket socket;
        final OutputStream out;
        final BufferedReader in;

        RawClient(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(10_000);
            out = socket.getOutputStream();
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        }

        void send(String line) throws IOException {
            out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            out.flush();
        }

        String read() throws IOException {
            try {
                return in.readLine();
            } catch (java.net.SocketException reset) {
                return null;
            }
        }

        String readUntil(String fragment) throws IOException {
            String line;
            while ((line = read()) != null && !line.contains(fragment)) {
                // skip game traffic (ticks, snapshots)
            }
            return line;
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
