package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GamePhase;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
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

/**
 * What docs/protocol.md promises about who hears what and when, stepped without sockets: the start
 * of the game for clients that come late, the seed kept from agents, the tolerance of a move's
 * {@code from}, the tick of {@code GameOver}, the audience of {@code AgentRemoved}.
 */
class AsSpecifiedTest {

    private static final long SEED = 7;
    private final Map<String, Vec3> places = new HashMap<>();
    private Simulation sim;
    private FakeSession early;
    private long seq = 100;

    @BeforeEach
    void setUp() {
        places.put("Guppy", Vec3.ground(0, 0));
        places.put("Bunny", Vec3.ground(0, 8));
        sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), SEED, "test", Recorder.NONE, List.of(),
                (name, radius) -> places.get(name));
        early = connect(1, Role.AGENT);
    }

    private FakeSession connect(long id, Role role) {
        FakeSession session = new FakeSession(id, role);
        sim.connected(session);
        sim.applyNow();
        return session;
    }

    /** Registers the agent and, as a lockstep client does, ends its setup turn, which starts a waiting game. */
    private void register(FakeSession session, String name) {
        sim.received(session, new RegisterMessage(++seq, name, TestWorlds.BODY, null));
        sim.applyNow();
        sim.received(session, new io.orchard.protocol.message.EndTurnMessage(++seq, 0));
        sim.applyNow();
    }

    private void tick(FakeSession session, io.orchard.protocol.message.ClientMessage... messages) {
        sim.beginTick();
        for (var message : messages) {
            sim.received(session, message);
        }
        sim.endTick();
    }

    @Nested
    class TheStartOfTheGame {

        @Test
        void theAgentWhoseRegistrationStartsTheGameHearsRegisteredThenGameStartedWithoutTheSeed() {
            register(early, "Guppy");
            List<ServerMessage> heard = early.received;
            int registered = heard.indexOf(early.last(RegisteredMessage.class));
            GameStartedMessage started = early.last(GameStartedMessage.class);
            assertThat(heard.indexOf(started)).isEqualTo(registered + 1);
            assertThat(started.seed()).isNull();
            assertThat(started.tick()).isZero();
            assertThat(started.timeLimit()).isEqualTo(30);
        }

        @Test
        void aViewerConnectedAtTheStartHearsTheSeed() {
            FakeSession viewer = connect(2, Role.VIEWER);
            register(early, "Guppy");
            assertThat(viewer.last(GameStartedMessage.class).seed()).isEqualTo(SEED);
        }

        @Test
        void clientsThatConnectAfterTheStartHearItOnceBeforeAnyTick() {
            register(early, "Guppy");
            tick(early);
            FakeSession agent = connect(3, Role.AGENT);
            FakeSession viewer = connect(4, Role.VIEWER);
            tick(early);
            register(agent, "Bunny");
            tick(early);

            assertThat(agent.all(GameStartedMessage.class)).singleElement()
                    .satisfies(started -> assertThat(started.seed()).isNull())
                    .satisfies(started -> assertThat(started.tick()).isZero())
                    .satisfies(started -> assertThat(started.fruitCount()).isEqualTo(4));
            assertThat(agent.received.get(0)).isInstanceOf(GameStartedMessage.class);
            assertThat(agent.received.indexOf(agent.last(RegisteredMessage.class)))
                    .isGreaterThan(agent.received.indexOf(agent.last(GameStartedMessage.class)));

            assertThat(viewer.all(GameStartedMessage.class)).singleElement()
                    .satisfies(started -> assertThat(started.seed()).isEqualTo(SEED));
            int snapshot = viewer.received.indexOf(viewer.last(WorldSnapshotMessage.class));
            int started = viewer.received.indexOf(viewer.last(GameStartedMessage.class));
            assertThat(started).isGreaterThan(snapshot)
                    .isLessThan(viewer.received.indexOf(viewer.all(TickMessage.class).get(0)));
            assertThat(early.all(GameStartedMessage.class)).hasSize(1);
        }

        @Test
        void aClientThatConnectsWhileTheGameWaitsHearsTheStartWhenItComes() {
            FakeSession viewer = connect(2, Role.VIEWER);
            assertThat(viewer.all(GameStartedMessage.class)).isEmpty();
            register(early, "Guppy");
            assertThat(viewer.all(GameStartedMessage.class)).hasSize(1);
        }

        @Test
        void aPausedGameIsStillOneThatStarted() {
            register(early, "Guppy");
            sim.togglePause();
            FakeSession late = connect(3, Role.AGENT);
            assertThat(late.all(GameStartedMessage.class)).hasSize(1);
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"WAITING, waiting", "RUNNING, running", "PAUSED, paused", "OVER, over"})
    void theWelcomeTellsTheTimeLimitAndThePhase(Phase phase, String wire) {
        if (phase != Phase.WAITING) {
            register(early, "Guppy");
        }
        if (phase == Phase.PAUSED) {
            sim.togglePause();
        } else if (phase == Phase.OVER) {
            sim.end("stopped");
        }
        WelcomeMessage welcome = sim.welcome(5, Role.AGENT, 2);
        assertThat(welcome.timeLimit()).isEqualTo(30);
        assertThat(welcome.phase()).isEqualTo(GamePhase.valueOf(phase.name()));
        assertThat(welcome.phase().wireName()).isEqualTo(wire);
    }

    @Nested
    class TheFromOfAMove {

        @BeforeEach
        void registerGuppy() {
            register(early, "Guppy");
        }

        private ActionResultMessage moved(Vec3 from) {
            tick(early, new MoveMessage(++seq, "Guppy", from, Vec3.ground(-5, 0)));
            return early.last(ActionResultMessage.class);
        }

        @ParameterizedTest(name = "from {0} units away")
        @CsvSource({"0, ACCEPTED", "0.3, ACCEPTED", "0.5, ACCEPTED", "0.51, REJECTED", "3, REJECTED"})
        void mayBeUpToHalfAUnitFromWhereTheAgentIs(double off, Outcome outcome) {
            ActionResultMessage result = moved(Vec3.ground(off, 0));
            assertThat(result.outcome()).isEqualTo(outcome);
            if (outcome == Outcome.REJECTED) {
                assertThat(result.reason()).endsWith("it may be at most 0.5 units away");
            }
        }

        @Test
        void leftOutWalksFromWhereTheAgentIsWhenTheMoveIsApplied() {
            tick(early, new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(-5, 0)));
            for (int i = 0; i < 4; i++) {
                tick(early);
            }
            assertThat(moved(Vec3.ZERO).outcome()).isEqualTo(Outcome.REJECTED);
            Vec3 meanwhile = sim.agents.get("Guppy").position;
            assertThat(meanwhile.x()).isLessThan(-1.5);

            tick(early, new MoveMessage(++seq, "Guppy", Vec3.ground(-5, 3)));
            ActionResultMessage result = early.last(ActionResultMessage.class);
            assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED);
            assertThat(result.duration()).isEqualTo(meanwhile.groundDistance(Vec3.ground(-5, 3)) / 10);
        }

        @Test
        void leftOutIsStillRejectedWhileTheGameDoesNotRun() {
            sim.togglePause();
            sim.received(early, new MoveMessage(++seq, "Guppy", Vec3.ground(-5, 0)));
            sim.applyNow();
            assertThat(early.last(ActionResultMessage.class).outcome()).isEqualTo(Outcome.REJECTED);
        }
    }

    @Test
    void anAxisThatIsNotUpIsNamedAsAPointNotAsAJavaRecord() {
        register(early, "Guppy");
        tick(early, new SetRotationMessage(++seq, "Guppy", new Rotation(new Vec3(1, 0, 0), 0.5)));
        assertThat(early.last(ActionResultMessage.class).reason())
                .isEqualTo("an agent turns only about the up axis (0, 1, 0), axis was (1.0, 0.0, 0.0)");
    }

    @Test
    void anUnregisteredTimeSensorIsARejectedActionNotAnError() {
        register(early, "Guppy");
        tick(early, new StartAnimationMessage(++seq, "Guppy", "GuppyTSWalk", true));
        ActionResultMessage result = early.last(ActionResultMessage.class);
        assertThat(result.outcome()).isEqualTo(Outcome.REJECTED);
        assertThat(result.reason()).isEqualTo("time sensor GuppyTSWalk not registered");
    }

    @Test
    void gameOverCarriesTheTickAfterTheLastOneTheNumberOfTicksTheGameRan() {
        register(early, "Guppy");
        long ticks = 0;
        while (sim.phase() == Phase.RUNNING) {
            tick(early);
            ticks++;
        }
        assertThat(ticks).isEqualTo(30 * 20);
        assertThat(early.last(TickMessage.class).tick()).isEqualTo(ticks - 1);
        assertThat(early.last(GameOverMessage.class).tick()).isEqualTo(ticks);
    }

    @Test
    void everyClientHearsThatAnAgentLeftAgentClientsToo() {
        FakeSession other = connect(2, Role.AGENT);
        FakeSession viewer = connect(3, Role.VIEWER);
        register(early, "Guppy");
        register(other, "Bunny");
        tick(early, new UnregisterMessage(++seq, "Guppy"));
        for (FakeSession session : List.of(early, other, viewer)) {
            assertThat(session.last(AgentRemovedMessage.class).agent()).isEqualTo("Guppy");
        }
    }
}
