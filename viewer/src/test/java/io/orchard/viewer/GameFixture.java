package io.orchard.viewer;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.StopAnimationMessage;
import io.orchard.protocol.message.TickMessage;
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
import io.orchard.server.WorldServer;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;

/**
 * Recorded games for the viewer's tests and measures, played on a real lockstep {@link WorldServer}
 * with a fixed seed by scripted agent clients, with a viewer connection open so that the recording
 * holds the world snapshot.
 *
 * <p>{@link #scripted} is the small garden of the screenshot tests: the agent Walker (the bundled
 * figure) walks north to a coconut, grasps it, nods and walks east; Broken registers with a model
 * that is not X3D and must show as a placeholder. {@link #crowd} has many figures wandering the
 * generated world of seed 1998, for frame-rate measures.
 */
public final class GameFixture {

    /** The garden of the scripted game: 60 by 60 units, the castle in the north-west, the river in the south. */
    public static final String GARDEN = """
            {
              "format": 1,
              "bounds": {"minX": -30, "minZ": -30, "maxX": 30, "maxZ": 30},
              "castle": {"footprint": [{"x": -26, "z": -26}, {"x": -16, "z": -26}, {"x": -16, "z": -18},
                                       {"x": -26, "z": -18}], "height": 7},
              "river": {"outline": [{"x": -30, "z": 8}, {"x": 30, "z": 8}, {"x": 30, "z": 14}, {"x": -30, "z": 14}]},
              "bridges": [
                {"id": "B1", "entryA": {"x": -12, "z": 6}, "entryB": {"x": -12, "z": 16}, "width": 3},
                {"id": "B2", "entryA": {"x": 16, "z": 6}, "entryB": {"x": 16, "z": 16}, "width": 3}
              ],
              "trees": [
                {"id": "T1", "kind": "tree", "position": {"x": 12, "z": -12}, "radius": 2.2, "height": 6.5},
                {"id": "T2", "kind": "tree", "position": {"x": -6, "z": 22}, "radius": 2, "height": 5.5},
                {"id": "T3", "kind": "tree", "position": {"x": 22, "z": 22}, "radius": 2.5, "height": 6}
              ],
              "tables": [
                {"id": "D1", "kind": "table", "position": {"x": -6, "z": -8}, "radius": 0.8, "height": 0.9}
              ],
              "fruit": [
                {"id": "F1", "kind": "coconut", "position": {"x": 4, "y": 0.35, "z": -6}},
                {"id": "F2", "kind": "tomato", "position": {"x": -1, "y": 0.15, "z": -3}},
                {"id": "F3", "kind": "banana", "position": {"x": -5.6, "y": 1.15, "z": -8}, "support": "D1"},
                {"id": "F4", "kind": "coconut", "position": {"x": 12.8, "y": 2.4, "z": -12}, "support": "T1"},
                {"id": "F5", "kind": "tomato", "position": {"x": 20, "y": 0.15, "z": 2}}
              ]
            }
            """;

    /** Where Walker starts; it faces north (heading 0) and walks to {@link #WALKER_GRASP_SPOT}. */
    public static final Vec3 WALKER_START = new Vec3(4, 0, -1.5);
    /** Where Walker stands to grasp coconut F1. */
    public static final Vec3 WALKER_GRASP_SPOT = new Vec3(4, 0, -5);
    /** Where Walker ends, east of the grasp spot. */
    public static final Vec3 WALKER_END = new Vec3(10, 0, -5);
    /** Where Broken stands, all game long. */
    public static final Vec3 BROKEN_AT = new Vec3(-2, 0, 3);
    /** The seed of both games. */
    public static final long SEED = 1998;

    static final Body WALKER_BODY = new Body(0.4, 1.6, 4, new Gripper("hands", 0.6, 0, 1.5), new Sight(12, 2.0));

    private static Path shared;

    private GameFixture() {
    }

    /** The scripted game, recorded once per test run and shared by the tests that only read it. */
    public static synchronized Path sharedScripted() throws Exception {
        if (shared == null) {
            Path dir = Files.createTempDirectory("orchard-viewer-game");
            dir.toFile().deleteOnExit();
            shared = scripted(dir);
            shared.toFile().deleteOnExit();
            dir.resolve("garden.json").toFile().deleteOnExit();
        }
        return shared;
    }

    /**
     * Plays the scripted game in the garden and records it.
     *
     * @return the recording, {@code recording.ndjson} in {@code dir}
     */
    public static Path scripted(Path dir) throws Exception {
        Path scenario = dir.resolve("garden.json");
        Files.writeString(scenario, GARDEN, StandardCharsets.UTF_8);
        Path recording = dir.resolve("recording.ndjson");
        Map<String, Vec3> places = Map.of("Walker", WALKER_START, "Broken", BROKEN_AT);
        BlockingQueue<ServerMessage> shown = new LinkedBlockingQueue<>();
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP).tickRate(20)
                .timeLimit(4).waitFor(2).scenario(scenario).record(recording)
                .placement((name, radius) -> places.get(name)).start();
             ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER,
                     "fixture-viewer", shown::add)) {
            awaitSnapshot(viewer, shown);
            BlockingQueue<ServerMessage> inbox = new LinkedBlockingQueue<>();
            try (ProtocolConnection agent = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT,
                    "fixture-script", inbox::add)) {
                request(agent, seq -> new RegisterMessage(seq, "Walker", WALKER_BODY, ModelSpec.bundled("figure")));
                request(agent, seq -> new RegisterTimeSensorMessage(seq, "Walker", "WalkerTSWalk"));
                request(agent, seq -> new RegisterTimeSensorMessage(seq, "Walker", "WalkerTSGrasp"));
                request(agent, seq -> new RegisterJointMessage(seq, "Walker", "Neck"));
                byte[] notX3d = "<X3D><Scene><Transform DEF='Broken'>".getBytes(StandardCharsets.UTF_8);
                ModelSpec broken = ModelSpec.of(ModelFormat.X3D, notX3d);
                request(agent, seq -> new RegisterMessage(seq, "Broken", WALKER_BODY, broken));
                agent.send(seq -> new EndTurnMessage(seq, 0)); // the setup turn: the game starts when it is over
                Map<Long, List<LongFunction<ClientMessage>>> script = new HashMap<>();
                at(script, 1, seq -> new SetRotationMessage(seq, "Walker", Rotation.heading(0)));
                at(script, 1, seq -> new MoveMessage(seq, "Walker", WALKER_START, WALKER_GRASP_SPOT));
                at(script, 1, seq -> new StartAnimationMessage(seq, "Walker", "WalkerTSWalk", true));
                at(script, 21, seq -> new StopAnimationMessage(seq, "Walker", "WalkerTSWalk"));
                at(script, 21, seq -> new StartAnimationMessage(seq, "Walker", "WalkerTSGrasp", false));
                at(script, 21, seq -> new GraspRequestMessage(seq, "Walker", "F1"));
                at(script, 24, seq -> new SetJointRotationMessage(seq, "Walker", "Neck",
                        new Rotation(new Vec3(1, 0, 0), -0.3)));
                at(script, 25, seq -> new SayMessage(seq, "Broken", "my model is broken, so I am a placeholder"));
                at(script, 30, seq -> new SetRotationMessage(seq, "Walker", Rotation.heading(-Math.PI / 2)));
                at(script, 30, seq -> new MoveMessage(seq, "Walker", WALKER_GRASP_SPOT, WALKER_END));
                at(script, 30, seq -> new StartAnimationMessage(seq, "Walker", "WalkerTSWalk", true));
                at(script, 61, seq -> new StopAnimationMessage(seq, "Walker", "WalkerTSWalk"));
                at(script, 62, seq -> new SayMessage(seq, "Walker", "one coconut, three points"));
                play(agent, inbox, tick -> script.getOrDefault(tick, List.of()));
            }
        }
        return recording;
    }

    /**
     * Plays a short game in the garden with one agent, {@code name}, standing at the origin with
     * {@code model}, its time sensors registered, sending {@code script}'s messages at their ticks
     * (20 a second), and records it.
     *
     * @return the recording, {@code <name>.ndjson} in {@code dir}
     */
    public static Path posing(Path dir, String name, ModelSpec model, List<String> timeSensors,
                              Map<Long, List<LongFunction<ClientMessage>>> script, double seconds) throws Exception {
        Path scenario = dir.resolve("garden.json");
        Files.writeString(scenario, GARDEN, StandardCharsets.UTF_8);
        Path recording = dir.resolve(name + ".ndjson");
        BlockingQueue<ServerMessage> shown = new LinkedBlockingQueue<>();
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP).tickRate(20)
                .timeLimit(seconds).waitFor(1).scenario(scenario).record(recording)
                .placement((agent, radius) -> new Vec3(0, 0, 0)).start();
             ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER,
                     "fixture-viewer", shown::add)) {
            awaitSnapshot(viewer, shown);
            BlockingQueue<ServerMessage> inbox = new LinkedBlockingQueue<>();
            try (ProtocolConnection agent = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT,
                    "fixture-poser", inbox::add)) {
                request(agent, seq -> new RegisterMessage(seq, name, WALKER_BODY, model));
                for (String sensor : timeSensors) {
                    request(agent, seq -> new RegisterTimeSensorMessage(seq, name, sensor));
                }
                agent.send(seq -> new EndTurnMessage(seq, 0));
                play(agent, inbox, tick -> script.getOrDefault(tick, List.of()));
            }
        }
        return recording;
    }

    /**
     * Plays a game of {@code agents} figures wandering the generated world of seed 1998 for
     * {@code seconds} simulated seconds, and records it.
     */
    public static Path crowd(Path dir, int agents, double seconds) throws Exception {
        Path recording = dir.resolve("crowd-" + agents + ".ndjson");
        BlockingQueue<ServerMessage> shown = new LinkedBlockingQueue<>();
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP).tickRate(20)
                .timeLimit(seconds).waitFor(agents).record(recording).start();
             ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER,
                     "fixture-viewer", shown::add)) {
            awaitSnapshot(viewer, shown);
            BlockingQueue<ServerMessage> inbox = new LinkedBlockingQueue<>();
            List<ProtocolConnection> clients = new ArrayList<>();
            Map<String, Vec3> where = new java.util.concurrent.ConcurrentHashMap<>();
            try {
                // One connection per agent, as each agent would have its own control client.
                for (int i = 0; i < agents; i++) {
                    String name = "Agent" + i;
                    boolean bunny = i % 3 == 2;
                    ProtocolConnection client = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT,
                            "fixture-crowd-" + i, message -> {
                                if (i0(name) == 0) {
                                    inbox.add(message);
                                }
                                if (message instanceof ActionResultMessage result && "Move".equals(result.action())
                                        && result.outcome() != Outcome.REJECTED && result.position() != null) {
                                    where.put(name, result.position());
                                }
                            });
                    clients.add(client);
                    RegisteredMessage registered = (RegisteredMessage) request(client, seq -> new RegisterMessage(seq,
                            name, WALKER_BODY, ModelSpec.bundled(bunny ? "bunny" : "figure")));
                    where.put(name, registered.position());
                    String sensor = name + (bunny ? "TSHop" : "TSWalk");
                    request(client, seq -> new RegisterTimeSensorMessage(seq, name, sensor));
                    request(client, seq -> new StartAnimationMessage(seq, name, sensor, true));
                    client.send(seq -> new EndTurnMessage(seq, 0)); // its setup turn
                }
                Random random = new Random(SEED);
                play(clients.get(0), inbox, tick -> {
                    for (int i = 0; i < agents; i++) {
                        String name = "Agent" + i;
                        ProtocolConnection client = clients.get(i);
                        try {
                            if ((tick + i) % 40 == 1) {
                                Vec3 from = where.get(name);
                                double heading = random.nextDouble() * 2 * Math.PI - Math.PI;
                                Vec3 to = new Vec3(from.x() - 6 * Math.sin(heading), 0, from.z() - 6 * Math.cos(heading));
                                client.send(seq -> new SetRotationMessage(seq, name, Rotation.heading(heading)));
                                client.send(seq -> new MoveMessage(seq, name, from, to));
                            }
                            if (i > 0) {
                                client.send(seq -> new EndTurnMessage(seq, tick));
                            }
                        } catch (IOException e) {
                            throw new IllegalStateException(e);
                        }
                    }
                    return List.of();
                });
            } finally {
                clients.forEach(ProtocolConnection::close);
            }
        }
        return recording;
    }

    private static int i0(String name) {
        return Integer.parseInt(name.substring("Agent".length()));
    }

    /** Waits until the viewer connection has the world, so that the recording holds its snapshot first. */
    private static void awaitSnapshot(ProtocolConnection viewer, BlockingQueue<ServerMessage> shown)
            throws InterruptedException {
        ServerMessage first;
        do {
            first = shown.poll(10, TimeUnit.SECONDS);
        } while (first != null && !(first instanceof io.orchard.protocol.message.WorldSnapshotMessage));
        if (first == null || !viewer.isOpen()) {
            throw new IllegalStateException("the fixture's viewer connection got no world snapshot");
        }
    }

    /** Answers every tick with the script's messages and an EndTurn until the game is over. */
    private static void play(ProtocolConnection agent, BlockingQueue<ServerMessage> inbox,
                             java.util.function.LongFunction<List<LongFunction<ClientMessage>>> script) throws Exception {
        while (true) {
            ServerMessage message = inbox.poll(20, TimeUnit.SECONDS);
            if (message == null) {
                throw new IllegalStateException("the server went quiet");
            }
            if (message instanceof TickMessage tick) {
                for (LongFunction<ClientMessage> action : script.apply(tick.tick())) {
                    agent.send(action);
                }
                agent.send(seq -> new EndTurnMessage(seq, tick.tick()));
            } else if (message instanceof ActionResultMessage result && result.outcome() == Outcome.REJECTED
                    && !"Move".equals(result.action())) {
                throw new IllegalStateException("the script's " + result.action() + " was refused: " + result.reason());
            } else if (message instanceof GameOverMessage) {
                return;
            }
        }
    }

    private static ServerMessage request(ProtocolConnection connection, LongFunction<? extends ClientMessage> message)
            throws Exception {
        ServerMessage reply = (ServerMessage) connection.request(message).get(10, TimeUnit.SECONDS);
        if (reply instanceof io.orchard.protocol.message.ErrorMessage error) {
            throw new IllegalStateException("the server refused: " + error.text());
        }
        return reply;
    }

    static void at(Map<Long, List<LongFunction<ClientMessage>>> script, long tick,
                           LongFunction<ClientMessage> message) {
        script.computeIfAbsent(tick, t -> new ArrayList<>()).add(message);
    }

    /** Writes the recordings for the viewer's measures: {@code GameFixture DIR AGENTS SECONDS}. */
    public static void main(String[] args) throws Exception {
        Path dir = Path.of(args[0]);
        Files.createDirectories(dir);
        if (args.length > 1) {
            System.out.println(crowd(dir, Integer.parseInt(args[1]), Double.parseDouble(args[2])));
        } else {
            System.out.println(scripted(dir));
        }
    }
}
