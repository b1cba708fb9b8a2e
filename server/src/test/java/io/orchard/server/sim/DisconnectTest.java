package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.assertj.core.data.Offset;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Connections that drop at awkward moments: in the middle of a walk, of a grasp, of a
 * registration. The world stays consistent, the agent leaves and is announced, its score stays.
 */
class DisconnectTest {

    private final Map<String, Vec3> places = new HashMap<>();
    private Simulation sim;
    private FakeSession guppy;
    private FakeSession bunny;
    private FakeSession viewer;
    private long seq = 100;
    /** The wall clock that a dropped agent's reservation runs on, in nanoseconds. */
    private long now;

    @BeforeEach
    void setUp() {
        places.put("Guppy", Vec3.ground(0, 0));
        places.put("Bunny", Vec3.ground(-20, -15));
        sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), 7, "test", Recorder.NONE, List.of(),
                (name, radius) -> places.get(name));
        sim.registrations.departed.clock = () -> now;
        guppy = new FakeSession(1, Role.AGENT);
        bunny = new FakeSession(2, Role.AGENT);
        viewer = new FakeSession(3, Role.VIEWER);
        sim.connected(guppy);
        sim.connected(bunny);
        sim.connected(viewer);
        sim.applyNow();
        register(guppy, "Guppy");
        register(bunny, "Bunny");
    }

    /** Registers an agent and ends the setup turn (the first starts the game). */
    private RegisteredMessage register(FakeSession session, String name) {
        sim.received(session, new RegisterMessage(++seq, name, TestWorlds.BODY, null));
        sim.received(session, new EndTurnMessage(++seq, 0));
        sim.applyNow();
        return session.last(RegisteredMessage.class);
    }

    private void tick(FakeSession session, ClientMessage... messages) {
        sim.beginTick();
        for (ClientMessage message : messages) {
            sim.received(session, message);
        }
        sim.endTick();
    }

    private void ticks(int count) {
        for (int i = 0; i < count; i++) {
            tick(guppy);
        }
    }

    private Score scoreOf(String agent) {
        return sim.ranking().stream().filter(s -> s.agent().equals(agent)).findFirst().orElseThrow();
    }

    @Test
    void anAgentDroppedMidWalkLeavesNoTraceInTheWayOfOthers() {
        tick(guppy, new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(-10, 0)));
        ticks(5);
        Vec3 where = sim.agents.get("Guppy").position;
        assertThat(where.x()).isBetween(-6.0, -1.0);
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        assertThat(viewer.last(AgentRemovedMessage.class).agent()).isEqualTo("Guppy");
        assertThat(viewer.last(AgentRemovedMessage.class).reason()).isEqualTo("connection closed");
        assertThat(sim.agentNames()).containsExactly("Bunny");
        assertThat(scoreOf("Guppy").points()).isZero();
        // Bunny walks right through the place Guppy stood when it dropped: nothing is left there.
        Vec3 from = sim.agents.get("Bunny").position;
        tick(bunny, new MoveMessage(++seq, "Bunny", from, Vec3.ground(where.x(), where.z() - 1)));
        ActionResultMessage walk = bunny.last(ActionResultMessage.class);
        assertThat(walk.outcome()).as(walk.reason()).isEqualTo(Outcome.ACCEPTED);
    }

    @Test
    void anAgentDroppedMidGraspTakesNoFruitAndTheFruitStaysForOthers() {
        tick(guppy, new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)),
                new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
        ticks(10);
        sim.beginTick();
        sim.received(guppy, new GraspRequestMessage(++seq, "Guppy", "F1"));
        sim.disconnected(guppy, "connection closed");
        sim.endTick();
        assertThat(guppy.all(GraspResultMessage.class)).isEmpty();
        assertThat(viewer.all(FruitEatenMessage.class)).isEmpty();
        assertThat(sim.fruitLeft()).isEqualTo(4);
        assertThat(scoreOf("Guppy").fruit()).isZero();
        assertThat(viewer.last(AgentRemovedMessage.class).agent()).isEqualTo("Guppy");
    }

    @Test
    void aScoreOutlivesTheConnectionThatEarnedIt() {
        tick(guppy, new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)),
                new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
        ticks(10);
        tick(guppy, new GraspRequestMessage(++seq, "Guppy", "F1"));
        assertThat(guppy.last(GraspResultMessage.class).success()).isTrue();
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        assertThat(scoreOf("Guppy")).isEqualTo(new Score("Guppy", 1, 1));
        assertThat(sim.fruitLeft()).isEqualTo(3);
    }

    @Test
    void aConnectionThatDropsRightAfterRegisteringLeavesAnAnnouncedAgentAndANameFreeOnceItsReservationIsOver() {
        FakeSession carrot = new FakeSession(4, Role.AGENT);
        sim.connected(carrot);
        sim.received(carrot, new RegisterMessage(++seq, "Carrot", TestWorlds.BODY, null));
        sim.disconnected(carrot, "connection closed");
        sim.applyNow();
        assertThat(viewer.last(AgentAddedMessage.class).agent().name()).isEqualTo("Carrot");
        assertThat(viewer.last(AgentRemovedMessage.class).agent()).isEqualTo("Carrot");
        assertThat(sim.agentNames()).containsExactly("Bunny", "Guppy"); // by name
        assertThat(scoreOf("Carrot").points()).isZero();
        now += Duration.ofSeconds(60).toNanos(); // the name's reservation for its controller is over
        FakeSession again = new FakeSession(5, Role.AGENT);
        sim.connected(again);
        sim.applyNow();
        assertThat(register(again, "Carrot").agent()).isEqualTo("Carrot");
    }

    @Test
    void aRegistrationThatArrivesAfterItsConnectionClosedIsIgnored() {
        FakeSession late = new FakeSession(4, Role.AGENT);
        sim.connected(late);
        sim.disconnected(late, "connection closed");
        sim.received(late, new RegisterMessage(++seq, "Late", TestWorlds.BODY, null));
        sim.applyNow();
        assertThat(sim.agentNames()).doesNotContain("Late");
        assertThat(viewer.all(AgentAddedMessage.class)).noneMatch(a -> a.agent().name().equals("Late"));
    }

    @Test
    void aControllerThatReconnectsWithItsTokenGetsItsAgentBackWhereItStood() {
        String token = guppy.last(RegisteredMessage.class).resumeToken();
        assertThat(token).hasSize(32);
        tick(guppy, new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(-5, 0)), new SetRotationMessage(++seq,
                "Guppy", Rotation.heading(1)));
        ticks(12);
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        FakeSession back = new FakeSession(6, Role.AGENT);
        sim.connected(back);
        sim.received(back, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, token));
        sim.applyNow();
        RegisteredMessage again = back.last(RegisteredMessage.class);
        assertThat(again.position().x()).isEqualTo(-5, Offset.offset(1e-9));
        assertThat(again.heading()).isEqualTo(1);
        assertThat(again.resumeToken()).isEqualTo(token);
        assertThat(viewer.last(AgentAddedMessage.class).agent().position()).isEqualTo(again.position());
    }

    @Test
    void withoutItsTokenADroppedAgentsNameStartsAfreshOnceItsReservationIsOver() {
        String token = guppy.last(RegisteredMessage.class).resumeToken();
        tick(guppy, new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(-5, 0)));
        ticks(12);
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        now += Duration.ofSeconds(60).toNanos();
        FakeSession other = new FakeSession(6, Role.AGENT);
        sim.connected(other);
        sim.received(other, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, "0".repeat(32)));
        sim.applyNow();
        RegisteredMessage fresh = other.last(RegisteredMessage.class);
        assertThat(fresh.position()).isEqualTo(Vec3.ZERO);
        assertThat(fresh.resumeToken()).isNotEqualTo(token);
    }

    @Test
    void aDroppedAgentsNameAndScoreAreKeptForItsControllerAndRefusedToOthersSayingWhenTheyFreeUp() {
        String token = guppy.last(RegisteredMessage.class).resumeToken();
        tick(guppy, new SetRotationMessage(++seq, "Guppy", Rotation.heading(Math.PI)),
                new MoveMessage(++seq, "Guppy", Vec3.ZERO, Vec3.ground(0, 4)));
        ticks(10);
        tick(guppy, new GraspRequestMessage(++seq, "Guppy", "F1"));
        assertThat(guppy.last(GraspResultMessage.class).success()).isTrue();
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        now += Duration.ofMillis(2_500).toNanos();

        FakeSession squatter = new FakeSession(6, Role.AGENT);
        sim.connected(squatter);
        sim.received(squatter, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null));
        sim.applyNow();
        ErrorMessage refused = squatter.last(ErrorMessage.class);
        assertThat(refused.code()).isEqualTo(ErrorCode.NAME_IN_USE);
        assertThat(refused.text()).isEqualTo("agent 'Guppy' left 2 s ago and its name and score are kept for its "
                + "controller, who gets them back by registering it with its resumeToken; the name frees up in 58 s");
        now += Duration.ofMillis(57_000).toNanos();
        sim.received(squatter, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, "0".repeat(32)));
        sim.applyNow();
        assertThat(squatter.last(ErrorMessage.class).text()).endsWith("the name frees up in 1 s");
        assertThat(squatter.all(RegisteredMessage.class)).isEmpty();

        FakeSession back = new FakeSession(7, Role.AGENT);
        sim.connected(back);
        sim.received(back, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, token));
        sim.applyNow();
        assertThat(back.last(RegisteredMessage.class).position().z()).isEqualTo(4, Offset.offset(1e-9));
        assertThat(scoreOf("Guppy")).isEqualTo(new Score("Guppy", 1, 1));
    }

    @Test
    void theControllerGetsItsAgentBackEvenAfterTheReservationAsLongAsNoOneElseTookTheName() {
        String token = guppy.last(RegisteredMessage.class).resumeToken();
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        now += Duration.ofMinutes(10).toNanos();
        FakeSession back = new FakeSession(6, Role.AGENT);
        sim.connected(back);
        sim.received(back, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null, token));
        sim.applyNow();
        assertThat(back.last(RegisteredMessage.class).resumeToken()).isEqualTo(token);
    }

    @Test
    void aReservationOfZeroFreesADroppedAgentsNameAtOnce() {
        sim.reserveDroppedNames(Duration.ZERO);
        sim.disconnected(guppy, "connection closed");
        ticks(1);
        FakeSession other = new FakeSession(6, Role.AGENT);
        sim.connected(other);
        sim.received(other, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null));
        sim.applyNow();
        assertThat(other.all(ErrorMessage.class)).isEmpty();
        assertThat(other.last(RegisteredMessage.class).agent()).isEqualTo("Guppy");
    }

    @Test
    void aNegativeReservationIsRefusedNamingIt() {
        org.assertj.core.api.Assertions.assertThatIllegalArgumentException()
                .isThrownBy(() -> sim.reserveDroppedNames(Duration.ofSeconds(-1)))
                .withMessage("the reservation of a dropped agent's name must be zero or more, was PT-1S");
    }
}
