package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.World;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A game saved at the end of a tick and continued from the file. */
class CheckpointTest {

    private static final SimulationConfig CONFIG = new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
            Duration.ofSeconds(1), 8, BodyLimits.DEFAULT);

    @TempDir
    Path dir;

    private final Map<String, Vec3> places = new HashMap<>();
    private final List<Message> recorded = new ArrayList<>();
    private Simulation sim;
    private FakeSession agents;
    private long seq = 100;
    private String guppyToken;
    private String bunnyToken;

    private Simulation simulation(World world) {
        Recorder recorder = new Recorder() {
            @Override
            public void accepted(long tick, double time, String client, Message message) {
                recorded.add(message);
            }

            @Override
            public void sent(long tick, double time, Audience to, String client, Message message) {
                recorded.add(message);
            }

            @Override
            public void close() {}
        };
        return new Simulation(world, CONFIG, 7, "test", recorder, List.of(), (name, radius) -> places.get(name));
    }

    @BeforeEach
    void playAWhile() {
        places.put("Guppy", Vec3.ground(0, 0));
        places.put("Bunny", Vec3.ground(-20, -15));
        sim = simulation(TestWorlds.small());
        agents = new FakeSession(1, Role.AGENT);
        sim.connected(agents);
        sim.received(agents, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null));
        sim.received(agents, new RegisterMessage(++seq, "Bunny", TestWorlds.BODY, null));
        sim.received(agents, new RegisterJointMessage(++seq, "Guppy", "LeftKnee"));
        sim.received(agents, new EndTurnMessage(++seq, 0)); // the setup turn: the game starts
        sim.applyNow();
        List<RegisteredMessage> registered = agents.all(RegisteredMessage.class);
        guppyToken = registered.get(0).resumeToken();
        bunnyToken = registered.get(1).resumeToken();
        tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)),
                new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
        for (int i = 0; i < 10; i++) {
            tick();
        }
        tick(new GraspRequestMessage(++seq, "Guppy", "F1"));
        assertThat(agents.last(GraspResultMessage.class).success()).isTrue();
    }

    private void tick(io.orchard.protocol.message.ClientMessage... messages) {
        tick(sim, agents, messages);
    }

    private static void tick(Simulation sim, FakeSession session, io.orchard.protocol.message.ClientMessage... messages) {
        sim.beginTick();
        for (var message : messages) {
            sim.received(session, message);
        }
        sim.endTick();
    }

    private Simulation restored() throws Exception {
        Path file = dir.resolve("game.checkpoint.json");
        CheckpointFile.write(sim.checkpoint(), file);
        Checkpoint saved = CheckpointFile.read(file);
        Simulation again = simulation(World.fromScenario(saved.world()));
        again.restore(saved);
        return again;
    }

    @Test
    void aCheckpointReadsBackAsWritten() throws Exception {
        Checkpoint checkpoint = sim.checkpoint();
        Path file = dir.resolve("cp.json");
        CheckpointFile.write(checkpoint, file);
        assertThat(CheckpointFile.read(file)).isEqualTo(checkpoint);
        assertThat(checkpoint.tick()).isEqualTo(12);
        assertThat(checkpoint.world().fruit()).extracting(f -> f.id()).doesNotContain("F1").hasSize(3);
        assertThat(checkpoint.scores()).contains(new Score("Guppy", 1, 1));
        assertThat(checkpoint.agents()).extracting(Checkpoint.SavedAgent::name).containsExactly("Bunny", "Guppy"); // by name
        assertThat(checkpoint.agents().get(1).joints()).containsExactly("LeftKnee"); // Guppy's
        assertThat(java.nio.file.Files.list(dir)).as("no temporary file is left").containsExactly(file);
    }

    @Test
    void aRestoredGameIsTheSavedOneWithItsAgentsWaiting() throws Exception {
        Checkpoint before = sim.checkpoint();
        Simulation again = restored();
        assertThat(again.tick()).isEqualTo(sim.tick());
        assertThat(again.time()).isEqualTo(sim.time());
        assertThat(again.fruitLeft()).isEqualTo(3);
        assertThat(again.ranking()).isEqualTo(sim.ranking());
        assertThat(again.agentNames()).isEmpty();
        assertThat(again.waitingAgents()).containsExactly("Bunny", "Guppy");
        assertThat(again.phase()).isEqualTo(Phase.PAUSED);
        Checkpoint after = again.checkpoint();
        assertThat(after.agents()).isEqualTo(before.agents());
        assertThat(after.world()).isEqualTo(before.world());
    }

    @Test
    void waitingAgentsComeBackOnlyWithTheirTokensAndTheGameGoesOnWhenAllAreBack() throws Exception {
        Simulation again = restored();
        FakeSession session = new FakeSession(1, Role.AGENT);
        again.connected(session);
        again.received(session, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null));
        again.received(session, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, bunnyToken));
        again.applyNow();
        assertThat(session.all(ErrorMessage.class)).extracting(ErrorMessage::code)
                .containsExactly(ErrorCode.NAME_IN_USE, ErrorCode.NAME_IN_USE);
        again.received(session, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, guppyToken));
        again.applyNow();
        RegisteredMessage guppy = session.last(RegisteredMessage.class);
        assertThat(guppy.position()).isEqualTo(sim.agents.get("Guppy").position);
        assertThat(guppy.heading()).isEqualTo(sim.agents.get("Guppy").heading);
        assertThat(again.agents.get("Guppy").joints).containsExactly("LeftKnee");
        assertThat(again.phase()).as("Bunny is still away").isEqualTo(Phase.PAUSED);
        again.received(session, new RegisterMessage(++seq, "Bunny", TestWorlds.BODY, null, bunnyToken));
        again.applyNow();
        assertThat(again.phase()).isEqualTo(Phase.RUNNING);
        assertThat(again.waitingAgents()).isEmpty();
    }

    @Test
    void theRestoredGameDrawsWhatTheUninterruptedOneWouldHave() throws Exception {
        Simulation again = restored();
        FakeSession other = new FakeSession(2, Role.AGENT);
        FakeSession otherAgain = new FakeSession(2, Role.AGENT);
        sim.connected(other);
        again.connected(otherAgain);
        sim.received(other, new RegisterMessage(++seq, "Carrot", TestWorlds.BODY, null));
        again.received(otherAgain, new RegisterMessage(seq, "Carrot", TestWorlds.BODY, null));
        sim.applyNow();
        again.applyNow();
        RegisteredMessage original = other.last(RegisteredMessage.class);
        RegisteredMessage resumed = otherAgain.last(RegisteredMessage.class);
        assertThat(resumed.position()).isEqualTo(original.position());
        assertThat(resumed.heading()).isEqualTo(original.heading());
    }

    @Test
    void recordingsKeepNoResumeToken() throws Exception {
        Simulation again = restored();
        FakeSession session = new FakeSession(1, Role.AGENT);
        again.connected(session);
        again.received(session, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, guppyToken));
        again.applyNow();
        assertThat(recorded).filteredOn(m -> m instanceof RegisteredMessage).isNotEmpty()
                .allSatisfy(m -> assertThat(((RegisteredMessage) m).resumeToken()).isNull());
        assertThat(recorded).filteredOn(m -> m instanceof RegisterMessage).isNotEmpty()
                .allSatisfy(m -> assertThat(((RegisterMessage) m).resumeToken()).isNull());
    }
}
