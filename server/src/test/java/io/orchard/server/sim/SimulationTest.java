package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.JointRotatedMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The simulation stepped tick by tick with a fixed world, fixed places and no sockets. */
class SimulationTest {

    private final Map<String, Vec3> places = new HashMap<>();
    private Simulation sim;
    private FakeSession agents;
    private FakeSession viewer;
    private long seq = 100;

    @BeforeEach
    void setUp() {
        places.put("Guppy", Vec3.ground(0, 0));
        places.put("Bunny", Vec3.ground(0, 8));
        sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), 7, "test", Recorder.NONE, List.of(),
                (name, radius) -> places.get(name));
        agents = new FakeSession(1, Role.AGENT);
        viewer = new FakeSession(2, Role.VIEWER);
        sim.connected(agents);
        sim.connected(viewer);
        sim.applyNow();
    }

    /** Registers an agent and ends the setup turn, which starts a lockstep game that waits for nobody else. */
    private void register(String name, Body body) {
        sim.received(agents, new RegisterMessage(++seq, name, body, null));
        sim.received(agents, new EndTurnMessage(++seq, 0));
        sim.applyNow();
    }

    /** Sends messages during one tick and ends it. */
    private void tick(io.orchard.protocol.message.ClientMessage... messages) {
        sim.beginTick();
        for (var message : messages) {
            sim.received(agents, message);
        }
        sim.endTick();
    }

    private void ticks(int count) {
        for (int i = 0; i < count; i++) {
            tick();
        }
    }

    private ActionResultMessage lastResult() {
        return agents.last(ActionResultMessage.class);
    }

    private MoveMessage move(String agent, Vec3 from, Vec3 to) {
        return new MoveMessage(++seq, agent, from, to);
    }

    @Test
    void viewerGetsTheSnapshotOnConnect() {
        WorldSnapshotMessage snapshot = viewer.last(WorldSnapshotMessage.class);
        assertThat(snapshot.obstacles()).extracting(o -> o.id()).containsExactlyInAnyOrder("T1", "D1");
        assertThat(snapshot.bridges()).hasSize(2);
        assertThat(snapshot.fruit()).hasSize(4);
    }

    @Test
    void registrationCapsTheBodyAndStartsTheGame() {
        Body greedy = new Body(0.5, 1.2, 50, new Gripper("hands", 9, 0, 9), new Sight(500, Math.PI));
        register("Guppy", greedy);
        RegisteredMessage registered = agents.last(RegisteredMessage.class);
        assertThat(registered.body().maxSpeed()).isEqualTo(20);
        assertThat(registered.body().gripper().reach()).isEqualTo(2.5);
        assertThat(registered.body().sight().range()).isEqualTo(60);
        assertThat(registered.position()).isEqualTo(Vec3.ground(0, 0));
        assertThat(viewer.last(AgentAddedMessage.class).agent().name()).isEqualTo("Guppy");
        assertThat(agents.last(GameStartedMessage.class).seed()).isNull();
        assertThat(viewer.last(GameStartedMessage.class).seed()).isEqualTo(7L);
        assertThat(sim.phase()).isEqualTo(Phase.RUNNING);
    }

    @Test
    void eachAgentGetsItsOwnSeedFromTheGamesSeedAndItsNameAndVersion1ClientsGetNone() {
        FakeSession old = new FakeSession(3, Role.AGENT);
        old.version = 1;
        sim.connected(old);
        register("Guppy", TestWorlds.BODY);
        register("Bunny", TestWorlds.BODY);
        sim.received(old, new RegisterMessage(++seq, "Carrot", TestWorlds.BODY, null));
        sim.applyNow();

        List<RegisteredMessage> registered = agents.all(RegisteredMessage.class);
        assertThat(registered.get(0).seed()).isEqualTo(AgentSeed.of(7, "Guppy")).isNotEqualTo(7L);
        assertThat(registered.get(1).seed()).isEqualTo(AgentSeed.of(7, "Bunny")).isNotEqualTo(registered.get(0).seed());
        assertThat(old.last(RegisteredMessage.class).seed()).isNull();
        assertThat(AgentSeed.of(8, "Guppy")).isNotEqualTo(AgentSeed.of(7, "Guppy"));
        // The documented derivation, so that any language can check it: SHA-256 of "orchard-agent-seed:7:Guppy".
        assertThat(AgentSeed.of(7, "Guppy")).isEqualTo(0x1E5B2B936DBD5C93L);
    }

    @Test
    void aNameInUseIsRefused() {
        register("Guppy", TestWorlds.BODY);
        register("Guppy", TestWorlds.BODY);
        assertThat(agents.last(ErrorMessage.class).code()).isEqualTo(ErrorCode.NAME_IN_USE);
    }

    @Test
    void aViewerCannotRegister() {
        sim.received(viewer, new RegisterMessage(5, "Sneaky", TestWorlds.BODY, null));
        sim.applyNow();
        assertThat(viewer.last(ErrorMessage.class).code()).isEqualTo(ErrorCode.WRONG_ROLE);
    }

    @Nested
    class Moving {

        @BeforeEach
        void registerGuppy() {
            register("Guppy", TestWorlds.BODY);
            viewer.received.clear();
        }

        @Test
        void aFreeMoveIsInterpolatedOverItsDuration() {
            tick(move("Guppy", Vec3.ZERO, Vec3.ground(-5, 0)));
            ActionResultMessage result = lastResult();
            assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED);
            assertThat(result.duration()).isEqualTo(0.5);
            AgentMovedMessage moved = viewer.last(AgentMovedMessage.class);
            assertThat(moved.from()).isEqualTo(Vec3.ZERO);
            assertThat(moved.to()).isEqualTo(Vec3.ground(-5, 0));
            assertThat(moved.duration()).isEqualTo(0.5);
            ticks(9);
            assertThat(sim.agents.get("Guppy").position.x()).isEqualTo(-5, org.assertj.core.data.Offset.offset(1e-9));
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = '|', textBlock = """
            tree in the way       | 0   | -20 | tree T1
            table in the way      | 20  | 0   | table D1
            river off the bridges | 10  | 30  | river
            castle in the way     | 35  | -35 | castle
            world's edge          | -60 | 0   | world
            """)
        void aBlockedMoveIsRejectedNamingTheObstacleAndChangesNothing(String name, double x, double z, String named) {
            tick(move("Guppy", Vec3.ZERO, Vec3.ground(x, z)));
            ActionResultMessage result = lastResult();
            assertThat(result.outcome()).isEqualTo(Outcome.REJECTED);
            assertThat(result.reason()).contains(named);
            assertThat(viewer.all(AgentMovedMessage.class)).isEmpty();
            ticks(3);
            assertThat(sim.agents.get("Guppy").position).isEqualTo(Vec3.ZERO);
        }

        @Test
        void aBridgeLetsTheAgentCrossTheRiver() {
            tick(move("Guppy", Vec3.ZERO, Vec3.ground(0, 32)));
            assertThat(lastResult().outcome()).isEqualTo(Outcome.ACCEPTED);
            ticks(80);
            assertThat(sim.agents.get("Guppy").position.z()).isEqualTo(32, org.assertj.core.data.Offset.offset(1e-9));
        }

        @Test
        void aMoveFromElsewhereIsATeleportAndIsRejected() {
            tick(move("Guppy", Vec3.ground(5, 5), Vec3.ground(6, 6)));
            assertThat(lastResult().outcome()).isEqualTo(Outcome.REJECTED);
            assertThat(lastResult().reason()).contains("is not where Guppy is");
        }

        @Test
        void aMoveIntoAnotherAgentStopsAtContact() {
            register("Bunny", TestWorlds.BODY);
            tick(move("Guppy", Vec3.ZERO, Vec3.ground(0, 15)));
            ActionResultMessage result = lastResult();
            assertThat(result.outcome()).isEqualTo(Outcome.BLOCKED);
            assertThat(result.reason()).isEqualTo("blocked by Bunny");
            assertThat(result.position().z()).isLessThan(7.0).isGreaterThan(6.9);
        }

        @Test
        void anotherConnectionCannotDriveTheAgent() {
            FakeSession intruder = new FakeSession(3, Role.AGENT);
            sim.connected(intruder);
            sim.applyNow();
            sim.beginTick();
            sim.received(intruder, move("Guppy", Vec3.ZERO, Vec3.ground(1, 1)));
            sim.endTick();
            assertThat(intruder.last(ErrorMessage.class).code()).isEqualTo(ErrorCode.NOT_YOUR_AGENT);
            assertThat(viewer.all(AgentMovedMessage.class)).isEmpty();
        }
    }

    @Nested
    class Joints {

        @BeforeEach
        void registerGuppy() {
            register("Guppy", TestWorlds.BODY);
        }

        @Test
        void anUnregisteredJointIsRejectedAndARegisteredOneTurns() {
            Rotation bend = new Rotation(new Vec3(1, 0, 0), 0.5);
            tick(new SetJointRotationMessage(++seq, "Guppy", "LeftKnee", bend));
            assertThat(lastResult().reason()).isEqualTo("joint LeftKnee not registered");
            assertThat(viewer.all(JointRotatedMessage.class)).isEmpty();
            tick(new RegisterJointMessage(++seq, "Guppy", "LeftKnee"),
                    new SetJointRotationMessage(++seq, "Guppy", "LeftKnee", bend));
            assertThat(lastResult().outcome()).isEqualTo(Outcome.ACCEPTED);
            assertThat(viewer.last(JointRotatedMessage.class).rotation()).isEqualTo(bend);
        }

        @Test
        void anAgentTurnsOnlyAboutTheUpAxis() {
            tick(new SetRotationMessage(++seq, "Guppy", new Rotation(new Vec3(1, 0, 0), 1)));
            assertThat(lastResult().outcome()).isEqualTo(Outcome.REJECTED);
            tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(1)));
            assertThat(sim.agents.get("Guppy").heading).isEqualTo(1);
        }
    }

    @Nested
    class Perceiving {

        @BeforeEach
        void registerGuppyFacingNorth() {
            register("Guppy", TestWorlds.BODY);
            tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(0)));
        }

        @Test
        void perceptionArrivesInTheTickAfterTheRequest() {
            tick(new PerceptionRequestMessage(++seq, "Guppy", 0));
            assertThat(agents.all(PerceptionMessage.class)).isEmpty();
            sim.beginTick();
            PerceptionMessage perception = agents.last(PerceptionMessage.class);
            assertThat(perception.tick()).isEqualTo(sim.tick());
            assertThat(agents.received.indexOf(perception))
                    .isGreaterThan(agents.received.indexOf(agents.last(TickMessage.class)));
            PerceivedObject tree = perception.objects().stream().filter(o -> o.id().equals("T1")).findFirst().orElseThrow();
            assertThat(tree.at().distance()).isEqualTo(10);
            assertThat(tree.at().bearing()).isEqualTo(0);
            // F1 lies behind Guppy (south), outside its half-circle view; D1 is east, at the edge of view.
            assertThat(perception.fruit()).extracting(f -> f.id()).doesNotContain("F1");
            assertThat(agents.last(CastlePerceptionMessage.class).sector()).isEqualTo(Sector.NORTH_EAST);
            assertThat(agents.last(LandmarkPerceptionMessage.class).river()).isNull();
            sim.endTick();
            sim.beginTick();
            assertThat(agents.all(PerceptionMessage.class)).hasSize(1);
        }

        @Test
        void turningAroundBringsTheRiverAndTheBridgesIntoView() {
            tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)),
                    new PerceptionRequestMessage(++seq, "Guppy", 0));
            sim.beginTick();
            LandmarkPerceptionMessage landmarks = agents.last(LandmarkPerceptionMessage.class);
            assertThat(landmarks.river()).isNotNull();
            assertThat(landmarks.river().nearest().distance()).isEqualTo(20);
            assertThat(landmarks.bridges()).extracting(b -> b.id()).contains("B1");
            assertThat(agents.last(PerceptionMessage.class).fruit()).extracting(f -> f.id()).contains("F1");
        }

        @Test
        void theCastleHidesWhatLiesBehindIt() {
            places.put("Scout", Vec3.ground(35, -15));
            register("Scout", TestWorlds.BODY);
            tick(new SetRotationMessage(++seq, "Scout", Rotation.heading(0)),
                    new PerceptionRequestMessage(++seq, "Scout", 0));
            sim.beginTick();
            PerceptionMessage seen = agents.all(PerceptionMessage.class).stream()
                    .filter(p -> p.agent().equals("Scout")).findFirst().orElseThrow();
            assertThat(seen.fruit()).extracting(f -> f.id()).doesNotContain("F5");
            assertThat(agents.last(CastlePerceptionMessage.class).sector()).isEqualTo(Sector.NORTH);
        }

        @Test
        void aSubscriptionDeliversEveryNTicks() {
            tick(new PerceptionRequestMessage(++seq, "Guppy", 5));
            for (int i = 0; i < 12; i++) {
                tick();
            }
            assertThat(agents.all(PerceptionMessage.class)).extracting(PerceptionMessage::tick)
                    .containsExactly(2L, 7L, 12L);
        }
    }

    @Nested
    class Grasping {

        @BeforeEach
        void registerGuppyFacingTheTomato() {
            register("Guppy", TestWorlds.BODY);
            tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)));
        }

        @Test
        void aFruitOutOfReachIsNotGrasped() {
            tick(new GraspRequestMessage(++seq, "Guppy", "F1"));
            GraspResultMessage result = agents.last(GraspResultMessage.class);
            assertThat(result.success()).isFalse();
            assertThat(result.reason()).contains("F1");
            assertThat(sim.fruitLeft()).isEqualTo(4);
        }

        @Test
        void aFruitInReachIsCollectedScoredAndAnnounced() {
            tick(move("Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
            ticks(10);
            tick(new GraspRequestMessage(++seq, "Guppy", "F1"));
            GraspResultMessage result = agents.last(GraspResultMessage.class);
            assertThat(result.success()).as(result.reason()).isTrue();
            assertThat(result.points()).isEqualTo(1);
            assertThat(agents.last(FruitEatenMessage.class).fruit()).isEqualTo("F1");
            assertThat(agents.last(ScoreUpdateMessage.class).scores().get(0).points()).isEqualTo(1);
            assertThat(viewer.last(FruitRemovedMessage.class).fruit()).isEqualTo("F1");
            assertThat(sim.fruitLeft()).isEqualTo(3);
            tick(new GraspRequestMessage(++seq, "Guppy", "F1"));
            assertThat(agents.last(GraspResultMessage.class).success()).isFalse();
        }

        @Test
        void twoAgentsGraspingOneFruitInOneTickGiveItToTheNearest() {
            places.put("Bunny", Vec3.ground(0, 5.7));
            register("Bunny", TestWorlds.BODY);
            tick(move("Guppy", Vec3.ZERO, Vec3.ground(0, 4.2)),
                    new SetRotationMessage(++seq, "Bunny", Rotation.heading(0)));
            ticks(10);
            tick(new GraspRequestMessage(++seq, "Guppy", "F1"), new GraspRequestMessage(++seq, "Bunny", "F1"));
            List<GraspResultMessage> results = agents.all(GraspResultMessage.class);
            assertThat(results).hasSize(2);
            GraspResultMessage bunny = results.stream().filter(r -> r.agent().equals("Bunny")).findFirst().orElseThrow();
            GraspResultMessage guppy = results.stream().filter(r -> r.agent().equals("Guppy")).findFirst().orElseThrow();
            assertThat(bunny.success()).isTrue();
            assertThat(guppy.success()).isFalse();
            assertThat(guppy.reason()).isEqualTo("fruit F1 was taken by Bunny");
        }
    }

    @Test
    void theGameEndsAtTheTimeLimitAndScoresSurviveADisconnect() {
        register("Guppy", TestWorlds.BODY);
        tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)), move("Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
        ticks(10);
        tick(new GraspRequestMessage(++seq, "Guppy", "F1"));
        sim.disconnected(agents, "connection closed");
        sim.beginTick();
        sim.endTick();
        assertThat(viewer.last(AgentRemovedMessage.class).agent()).isEqualTo("Guppy");
        while (sim.phase() == Phase.RUNNING) {
            sim.beginTick();
            sim.endTick();
        }
        GameOverMessage over = viewer.last(GameOverMessage.class);
        assertThat(over.reason()).isEqualTo("time limit reached");
        assertThat(over.ranking()).singleElement().satisfies(score -> {
            assertThat(score.agent()).isEqualTo("Guppy");
            assertThat(score.points()).isEqualTo(1);
        });
        assertThat(sim.time()).isEqualTo(30, org.assertj.core.data.Offset.offset(1e-9));
    }

    @Test
    void anInstructionIsRoutedToTheAgentsController() {
        register("Guppy", TestWorlds.BODY);
        sim.received(viewer, new InstructionMessage(9, "Guppy", "pick up the banana", "teacher"));
        sim.applyNow();
        assertThat(agents.last(InstructionMessage.class).text()).isEqualTo("pick up the banana");
        sim.received(viewer, new InstructionMessage(10, "Nobody", "hello", null));
        sim.applyNow();
        assertThat(viewer.last(ErrorMessage.class).code()).isEqualTo(ErrorCode.UNKNOWN_AGENT);
    }
}
