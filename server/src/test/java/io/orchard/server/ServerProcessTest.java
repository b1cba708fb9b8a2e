package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import io.orchard.server.sim.TestWorlds;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The server as a real process, killed without warning in the middle of a game and started again
 * from its checkpoint: nothing collected or scored is lost, and the recording it leaves is whole.
 */
class ServerProcessTest {

    private static final Body BODY = new Body(0.5, 1.2, 20, new Gripper("hands", 0.6, 0, 1.5), new Sight(40, Math.PI));
    private static final String TOKEN = "0123456789abcdef0123456789abcdef";
    private static final Pattern LISTENING = Pattern.compile("listening on port (\\d+)");

    @TempDir
    Path dir;

    private final List<Process> processes = new ArrayList<>();
    /** What the servers printed, line by line. */
    private final List<String> printed = java.util.Collections.synchronizedList(new ArrayList<>());

    @AfterEach
    void killAll() {
        processes.forEach(Process::destroyForcibly);
    }

    /** Starts {@code ServerMain} in a JVM of its own and returns the port it listens on. */
    private int startServer(Process[] started, String... args) throws Exception {
        return startServer(started, builder -> { }, new ArrayList<>(), args);
    }

    /**
     * Starts {@code ServerMain} in a JVM of its own, as {@code setUp} sets its process up, keeps
     * every line it writes in {@code written} and returns the port it listens on.
     */
    private int startServer(Process[] started, java.util.function.Consumer<ProcessBuilder> setUp, List<String> written,
                            String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), ServerMain.class.getName()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        setUp.accept(builder);
        Process process = builder.start();
        processes.add(process);
        started[0] = process;
        CompletableFuture<Integer> port = new CompletableFuture<>();
        Thread output = new Thread(() -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                String line;
                while ((line = lines.readLine()) != null) {
                    written.add(line);
                    printed.add(line);
                    Matcher matcher = LISTENING.matcher(line);
                    if (matcher.find()) {
                        port.complete(Integer.parseInt(matcher.group(1)));
                    }
                }
            } catch (IOException e) {
                // the process ended
            }
            port.completeExceptionally(new AssertionError("the server ended without listening"));
        }, "server-output");
        output.setDaemon(true);
        output.start();
        return port.get(60, TimeUnit.SECONDS);
    }

    /** A saved game with Guppy standing just north of tomato F1, facing it, waiting for its controller. */
    private Path savedGame() throws IOException {
        Checkpoint.SavedAgent guppy = new Checkpoint.SavedAgent("Guppy", BODY, null, Vec3.ground(0, 4), Math.PI,
                List.of(), List.of(), TOKEN);
        Checkpoint start = new Checkpoint(Checkpoint.FORMAT, 11, 50, ClockMode.REALTIME, 600, 0, "running", 10, 0.2,
                4, TestWorlds.small().toScenario(), List.of(guppy), List.of(new Score("Guppy", 0, 0)));
        Path file = dir.resolve("start.json");
        CheckpointFile.write(start, file);
        return file;
    }

    private static ServerMessage reply(ProtocolConnection connection,
                                       java.util.function.LongFunction<? extends io.orchard.protocol.message.ClientMessage> message)
            throws Exception {
        return (ServerMessage) connection.request(message).get(10, TimeUnit.SECONDS);
    }

    @Test
    void aServerStartedWithItsInputClosedRunsOnAndTakesItsOperatorTokenFromTheEnvironment() throws Exception {
        List<String> output = new java.util.concurrent.CopyOnWriteArrayList<>();
        Process[] server = new Process[1];
        int port = startServer(server, builder -> builder.environment().put(ServerMain.OPERATOR_TOKEN_VARIABLE,
                "op-env-5150"), output, "--port", "0", "--quiet");
        server[0].getOutputStream().close();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (output.stream().noneMatch(line -> line.startsWith("console input closed: the server runs on"))) {
            assertThat(System.nanoTime()).as("the server's word on its closed input; it wrote %s", output)
                    .isLessThan(deadline);
            Thread.sleep(20);
        }
        try (ProtocolConnection operator = ProtocolConnection.connect("127.0.0.1", port, Role.VIEWER, "test", null,
                "op-env-5150", m -> { })) {
            ServerMessage started = reply(operator, seq -> new GameControlMessage(seq, GameCommand.START));
            assertThat(started).isInstanceOfSatisfying(ActionResultMessage.class,
                    result -> assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED));
        }
        assertThat(server[0].isAlive()).as("the server after its input closed").isTrue();
    }

    @Test
    void withStopOnStdinCloseAServerWhoseInputClosesStops() throws Exception {
        Process[] server = new Process[1];
        List<String> output = new java.util.concurrent.CopyOnWriteArrayList<>();
        startServer(server, builder -> { }, output, "--port", "0", "--quiet", "--stop-on-stdin-close");
        server[0].getOutputStream().close();
        assertThat(server[0].waitFor(20, TimeUnit.SECONDS)).as("the server stopped; it wrote %s", output).isTrue();
        assertThat(server[0].exitValue()).isZero();
    }

    @Test
    void aServerKilledMidGameResumesWithEverythingCollectedAndAWholeRecording() throws Exception {
        Path checkpoint = dir.resolve("game.json");
        Path recording = dir.resolve("game.ndjson");
        Process[] first = new Process[1];
        int port = startServer(first, "--port", "0", "--resume", savedGame().toString(), "--checkpoint",
                checkpoint.toString(), "--checkpoint-every", "1", "--record", recording.toString(), "--quiet");
        try (ProtocolConnection agent = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test", m -> { })) {
            RegisteredMessage back = (RegisteredMessage) reply(agent, seq -> new RegisterMessage(seq, "Guppy", BODY, null,
                    TOKEN));
            assertThat(back.position()).isEqualTo(Vec3.ground(0, 4));
            GraspResultMessage tomato = (GraspResultMessage) reply(agent, seq -> new GraspRequestMessage(seq, "Guppy",
                    "F1"));
            assertThat(tomato.success()).as(tomato.reason()).isTrue();
            reply(agent, seq -> new SetRotationMessage(seq, "Guppy", Rotation.heading(0)));
            ActionResultMessage walk = (ActionResultMessage) reply(agent, seq -> new MoveMessage(seq, "Guppy",
                    Vec3.ground(0, 4), Vec3.ground(-20, -19)));
            assertThat(walk.outcome()).as(walk.reason()).isEqualTo(Outcome.ACCEPTED);
            // The walk takes its duration in simulated time; a realtime server on a busy machine may
            // take longer on the wall clock, so ask again until it has arrived (a grasp out of reach
            // changes nothing).
            Thread.sleep((long) (walk.duration() * 1000));
            long arrival = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            GraspResultMessage second;
            do {
                Thread.sleep(100);
                second = (GraspResultMessage) reply(agent, seq -> new GraspRequestMessage(seq, "Guppy", "F4"));
            } while (!second.success() && System.nanoTime() < arrival);
            assertThat(second.success()).as(second.reason()).isTrue();
            // The server saves after every tick that scored; wait for that file, then kill without warning.
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (!Files.exists(checkpoint) || CheckpointFile.read(checkpoint).world().fruit().size() != 2) {
                assertThat(System.nanoTime()).as("the checkpoint after the second fruit").isLessThan(deadline);
                Thread.sleep(20);
            }
            first[0].destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }

        MessageCodec codec = new MessageCodec();
        JsonMapper json = JsonMapper.builder().build();
        List<String> lines = Files.readAllLines(recording, StandardCharsets.UTF_8);
        assertThat(lines).isNotEmpty();
        for (String line : lines) {
            JsonNode record = json.readTree(line);
            codec.decode(record.get("msg").toString());
        }
        assertThat(lines).filteredOn(l -> l.contains("\"type\":\"FruitEaten\"")).hasSize(2);

        Process[] again = new Process[1];
        int resumed = startServer(again, "--port", "0", "--resume", checkpoint.toString(), "--quiet");
        BlockingQueue<ServerMessage> seen = new LinkedBlockingQueue<>();
        try (ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", resumed, Role.VIEWER, "test", seen::add);
             ProtocolConnection agent = ProtocolConnection.connect("127.0.0.1", resumed, Role.AGENT, "test", m -> { })) {
            WorldSnapshotMessage snapshot = (WorldSnapshotMessage) seen.poll(10, TimeUnit.SECONDS);
            assertThat(snapshot.fruit()).extracting(f -> f.id()).containsExactly("F2", "F5");
            assertThat(snapshot.scores()).containsExactly(new Score("Guppy", 2, 2));
            RegisteredMessage back = (RegisteredMessage) reply(agent, seq -> new RegisterMessage(seq, "Guppy", BODY, null,
                    TOKEN));
            assertThat(back.position().x()).isCloseTo(-20, org.assertj.core.data.Offset.offset(1e-6));
            assertThat(back.position().z()).isCloseTo(-19, org.assertj.core.data.Offset.offset(1e-6));
        }
    }

    /** A Tick as an agent heard it, and when. */
    private record Heard(long tick, long nanos) {}

    /** An agent that registers Guppy (with {@code token}, if any) and hears every tick, noting when. */
    private static ProtocolConnection guppy(int port, String token, List<Heard> ticks, String[] tokenGiven)
            throws Exception {
        ProtocolConnection agent = null;
        for (int attempt = 1; agent == null; attempt++) {
            try {
                agent = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "test", m -> {
                    if (m instanceof TickMessage tick) {
                        ticks.add(new Heard(tick.tick(), System.nanoTime()));
                    }
                });
            } catch (IOException e) {
                // A server just started on a busy machine may not read the first Hello within its
                // 5 s, its JVM still warming up; a second try finds it ready.
                if (attempt == 3 || !String.valueOf(e.getMessage()).contains("no Hello within")) {
                    throw e;
                }
            }
        }
        Reply reply = agent.request(seq -> new RegisterMessage(seq, "Guppy", BODY, null, token))
                .get(10, TimeUnit.SECONDS);
        assertThat(reply).isInstanceOf(RegisteredMessage.class);
        tokenGiven[0] = ((RegisteredMessage) reply).resumeToken();
        return agent;
    }

    private static long lastHeard(List<Heard> ticks) {
        synchronized (ticks) {
            return ticks.isEmpty() ? -1 : ticks.get(ticks.size() - 1).tick();
        }
    }

    private static void awaitTick(List<Heard> ticks, long tick) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (lastHeard(ticks) < tick) {
            assertThat(System.nanoTime()).as("tick %d within 60 s", tick).isLessThan(deadline);
            Thread.sleep(10);
        }
    }

    @Test
    void aServerKilledAfterManyTicksLosesAtMostOneCheckpointIntervalAndRecordsEveryTickItSent() throws Exception {
        Path checkpoint = dir.resolve("game.json");
        Path recording = dir.resolve("game.ndjson");
        double interval = 1;
        int tickRate = 20;
        Process[] first = new Process[1];
        int port = startServer(first, "--port", "0", "--seed", "5", "--tick-rate", "" + tickRate, "--checkpoint",
                checkpoint.toString(), "--checkpoint-every", "" + interval, "--record", recording.toString(),
                "--quiet");
        List<Heard> ticks = java.util.Collections.synchronizedList(new ArrayList<>());
        String[] token = new String[1];
        long killedAt;
        long lastSeen;
        try (ProtocolConnection agent = guppy(port, null, ticks, token)) {
            // Four intervals, so that a server saving less often than told would lose more than one.
            awaitTick(ticks, 4 * tickRate);
            killedAt = System.nanoTime();
            first[0].destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            lastSeen = lastHeard(ticks);
        }

        Checkpoint saved = CheckpointFile.read(checkpoint);
        long lastSavedTick = saved.tick() - 1; // the checkpoint was taken as that tick ended
        Heard savedTickHeard;
        synchronized (ticks) {
            savedTickHeard = ticks.stream().filter(h -> h.tick() == lastSavedTick).findFirst().orElseThrow();
        }
        double lostSeconds = (killedAt - savedTickHeard.nanos()) / 1e9;
        // One interval, plus the time to take and write a checkpoint and a tick's length, on a busy machine.
        double slack = 1;
        assertThat(lostSeconds).as("seconds of play lost").isLessThan(interval + slack);
        assertThat(lastSeen - lastSavedTick).as("ticks lost")
                .isLessThanOrEqualTo((long) ((interval + slack) * tickRate));

        // The recording was written tick by tick: it holds every tick up to the one before the last
        // the agent heard (the server hands a tick to its clients just before it writes it down).
        List<Long> recorded = new ArrayList<>();
        JsonMapper json = JsonMapper.builder().build();
        for (String line : Files.readAllLines(recording, StandardCharsets.UTF_8)) {
            JsonNode message = json.readTree(line).get("msg");
            if (message.get("type").asString().equals("Tick")) {
                recorded.add(message.get("tick").asLong());
            }
        }
        assertThat(recorded).startsWith(java.util.stream.LongStream.range(0, lastSeen).boxed()
                .toArray(Long[]::new));

        // Resumed, the game goes on from the saved tick once Guppy is back.
        Process[] again = new Process[1];
        int resumed = startServer(again, "--port", "0", "--resume", checkpoint.toString(), "--quiet");
        List<Heard> after = java.util.Collections.synchronizedList(new ArrayList<>());
        String[] sameToken = new String[1];
        try (ProtocolConnection agent = guppy(resumed, token[0], after, sameToken)) {
            assertThat(sameToken[0]).isEqualTo(token[0]);
            awaitTick(after, saved.tick() + 5);
            assertThat(after.get(0).tick()).isEqualTo(saved.tick());
        }
    }

    @Test
    void aServerAskedToEndSavesTheGameAndLeavesNoHalfWrittenCheckpoint() throws Exception {
        Path checkpoint = dir.resolve("game.json");
        Process[] server = new Process[1];
        int port = startServer(server, "--port", "0", "--seed", "5", "--checkpoint", checkpoint.toString(),
                "--checkpoint-every", "1", "--quiet");
        List<Heard> ticks = java.util.Collections.synchronizedList(new ArrayList<>());
        long lastSeen;
        try (ProtocolConnection agent = guppy(port, null, ticks, new String[1])) {
            awaitTick(ticks, 30);
            lastSeen = lastHeard(ticks);
            // SIGTERM, as a service manager ends it; through the handle, since Process.destroy()
            // would also close the pipe that the server's last words come through.
            server[0].toHandle().destroy();
            assertThat(server[0].waitFor(30, TimeUnit.SECONDS)).as("the server ended").isTrue();
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10); // the last lines may still be on their way
        while (!printed.contains("asked to end: the game is saved to " + checkpoint) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertThat(printed).contains("asked to end: the game is saved to " + checkpoint);
        try (java.util.stream.Stream<Path> files = Files.list(dir)) {
            assertThat(files).containsExactly(checkpoint);
        }
        assertThat(CheckpointFile.read(checkpoint).tick()).isGreaterThan(lastSeen);
    }
}
