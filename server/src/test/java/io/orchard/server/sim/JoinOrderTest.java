package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.KeepAliveMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.WorldGenerator;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A lockstep game of one seed gives the same record, byte for byte, whichever client connected,
 * registered, set up or acted first: the whole files are compared, not their sorted lines.
 */
class JoinOrderTest {

    private static final List<String> NAMES = List.of("Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner");

    @TempDir
    Path dir;

    private static Simulation simulation(long seed, Recorder recorder, Placement placement) {
        return new Simulation(WorldGenerator.standard(seed).generate(), new SimulationConfig(20, ClockMode.LOCKSTEP,
                30, NAMES.size(), Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), seed, "test", recorder, List.of(),
                placement);
    }

    /**
     * Plays 40 ticks of a scripted game: the clients connect in {@code order}, register in an order
     * and set up in another, both drawn from {@code shuffle}, and in every tick send their actions in
     * an order drawn anew. Returns the record.
     */
    private byte[] play(String file, List<String> order, long shuffle, Placement placement) throws IOException {
        return play(file, order, shuffle, placement, false);
    }

    /** As above; with {@code watched}, a viewer joins at tick 20 and a client sends a keep-alive. */
    private byte[] play(String file, List<String> order, long shuffle, Placement placement, boolean watched)
            throws IOException {
        Path path = dir.resolve(file);
        Random arrivals = new Random(shuffle);
        try (FileRecorder recorder = FileRecorder.open(path)) {
            Simulation sim = simulation(1998, recorder, placement);
            FakeSession viewer = new FakeSession(100 + arrivals.nextInt(100), Role.VIEWER);
            sim.connected(viewer);
            Map<String, FakeSession> clients = new LinkedHashMap<>();
            long id = 1;
            for (String name : order) {
                FakeSession client = new FakeSession(id++, Role.AGENT);
                clients.put(name, client);
                sim.connected(client);
                sim.applyNow();
            }
            List<String> registering = new ArrayList<>(order);
            Collections.shuffle(registering, arrivals);
            for (String name : registering) {
                sim.received(clients.get(name), new RegisterMessage(1, name, TestWorlds.BODY, null));
                sim.applyNow();
            }
            List<String> settingUp = new ArrayList<>(order);
            Collections.shuffle(settingUp, arrivals);
            for (String name : settingUp) {
                FakeSession client = clients.get(name);
                sim.received(client, new RegisterJointMessage(2, name, "Neck"));
                sim.applyNow();
                sim.received(client, new PerceptionRequestMessage(3, name, 5));
                sim.received(client, new EndTurnMessage(4, 0));
                sim.applyNow();
            }
            assertThat(sim.phase()).isEqualTo(Phase.RUNNING);
            for (long tick = 0; tick < 40; tick++) {
                if (watched && tick == 20) {
                    sim.connected(new FakeSession(99, Role.VIEWER));
                    sim.received(clients.get("Robot"), new KeepAliveMessage(100));
                    sim.applyNow();
                }
                sim.beginTick();
                List<String> acting = new ArrayList<>(order);
                Collections.shuffle(acting, arrivals);
                for (String name : acting) {
                    for (ClientMessage message : actions(sim, name, tick)) {
                        sim.received(clients.get(name), message);
                    }
                }
                sim.endTick();
            }
        }
        return Files.readAllBytes(path);
    }

    /** What agent {@code name} does in {@code tick}: turn, walk a little, say something, end its turn. */
    private static List<ClientMessage> actions(Simulation sim, String name, long tick) {
        long seq = 10 + tick * 4;
        Vec3 here = sim.agents.get(name).position;
        double angle = (name.length() + tick) * 0.7;
        Vec3 to = Vec3.ground(here.x() + 3 * Math.sin(angle), here.z() + 3 * Math.cos(angle));
        List<ClientMessage> messages = new ArrayList<>();
        if (tick % 5 == 0) {
            messages.add(new SetRotationMessage(seq, name, Rotation.heading(angle)));
            messages.add(new MoveMessage(seq + 1, name, here, to));
        }
        if (tick % 7 == 3) {
            messages.add(new SayMessage(seq + 2, name, name + " at tick " + tick));
        }
        messages.add(new EndTurnMessage(seq + 3, tick));
        return messages;
    }

    @Test
    void aGameGivesTheSameRecordWhateverOrderItsClientsCameAndActedIn() throws IOException {
        List<String> reversed = new ArrayList<>(NAMES);
        Collections.reverse(reversed);
        byte[] first = play("first.ndjson", NAMES, 1, (name, radius) -> null);

        assertThat(new String(first, java.nio.charset.StandardCharsets.UTF_8))
                .contains("\"dir\":\"in\",\"client\":\"Dwarf\"", "\"type\":\"Say\"", "\"type\":\"AgentMoved\"")
                .doesNotContain("\"session\"", "\"dir\":\"missed\"");
        assertThat(play("reversed.ndjson", reversed, 2, (name, radius) -> null)).isEqualTo(first);
        assertThat(play("shuffled.ndjson", List.of("Guppy", "Dwarf", "Roadrunner", "Bunny", "Robot"), 3,
                (name, radius) -> null)).isEqualTo(first);
    }

    @Test
    void aViewerCatchingUpAndAKeepAliveLeaveTheRecordAsItWas() throws IOException {
        byte[] unwatched = play("unwatched.ndjson", NAMES, 6, (name, radius) -> null);

        assertThat(play("watched.ndjson", NAMES, 6, (name, radius) -> null, true)).isEqualTo(unwatched);
    }

    @Test
    void agentsPlacedOnTopOfEachOtherAreSettledInTheOrderOfTheirNames() throws IOException {
        // Every agent wants the same spot: the first name keeps it, the others move on, whoever came first.
        Placement crowded = (name, radius) -> Vec3.ground(10, 10);
        List<String> reversed = new ArrayList<>(NAMES);
        Collections.reverse(reversed);

        byte[] first = play("first.ndjson", NAMES, 4, crowded);

        assertThat(play("reversed.ndjson", reversed, 5, crowded)).isEqualTo(first);
        Simulation sim = simulation(1998, Recorder.NONE, crowded);
        FakeSession viewer = new FakeSession(9, Role.VIEWER);
        sim.connected(viewer);
        for (String name : reversed) {
            FakeSession client = new FakeSession(NAMES.indexOf(name) + 1, Role.AGENT);
            sim.connected(client);
            sim.received(client, new RegisterMessage(1, name, TestWorlds.BODY, null));
            sim.received(client, new EndTurnMessage(2, 0));
            sim.applyNow();
        }
        assertThat(sim.agents.get("Bunny").position).isEqualTo(Vec3.ground(10, 10));
        assertThat(viewer.all(AgentMovedMessage.class)).extracting(AgentMovedMessage::agent)
                .containsExactly("Dwarf", "Guppy", "Roadrunner", "Robot");
        for (String a : NAMES) {
            for (String b : NAMES) {
                if (!a.equals(b)) {
                    assertThat(sim.agents.get(a).position.groundDistance(sim.agents.get(b).position))
                            .as("%s to %s", a, b).isGreaterThanOrEqualTo(2 * TestWorlds.BODY.radius());
                }
            }
        }
    }

    @Test
    void agentsAreListedByName() {
        Simulation sim = simulation(7, Recorder.NONE, (name, radius) -> null);
        long id = 10;
        for (String name : NAMES) {
            FakeSession client = new FakeSession(id++, Role.AGENT);
            sim.connected(client);
            sim.received(client, new RegisterMessage(id, name, TestWorlds.BODY, null));
        }
        sim.applyNow();

        assertThat(sim.agentNames()).containsExactly("Bunny", "Dwarf", "Guppy", "Roadrunner", "Robot");
    }

    @Test
    void whatClientsSayInOneTickIsAppliedInTheOrderOfTheirAgentsNames() {
        Simulation sim = simulation(7, Recorder.NONE, (name, radius) -> null);
        FakeSession viewer = new FakeSession(1, Role.VIEWER);
        sim.connected(viewer);
        FakeSession zed = new FakeSession(10, Role.AGENT); // connects first
        FakeSession amy = new FakeSession(11, Role.AGENT);
        sim.connected(zed);
        sim.connected(amy);
        sim.received(zed, new RegisterMessage(1, "Zed", TestWorlds.BODY, null));
        sim.received(amy, new RegisterMessage(1, "Amy", TestWorlds.BODY, null));
        sim.applyNow();

        sim.received(zed, new SayMessage(2, "Zed", "first to speak"));
        sim.received(amy, new SayMessage(2, "Amy", "second to speak"));
        sim.applyNow();

        assertThat(viewer.all(SayMessage.class)).extracting(SayMessage::agent).containsExactly("Amy", "Zed");
    }
}
