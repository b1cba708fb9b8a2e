package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Well-formed messages that ask for what the rules forbid: refused, and nothing changes. */
class HostileActionsTest {

    private Simulation sim;
    private FakeSession agents;
    private long seq = 100;

    @BeforeEach
    void setUp() {
        sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), 7, "test", Recorder.NONE, List.of(),
                (name, radius) -> name.equals("Guppy") ? Vec3.ground(0, 0) : null);
        agents = new FakeSession(1, Role.AGENT);
        sim.connected(agents);
        sim.received(agents, new RegisterMessage(++seq, "Guppy", TestWorlds.BODY, null));
        sim.received(agents, new EndTurnMessage(++seq, 0)); // the setup turn: the game starts
        sim.applyNow();
    }

    private void tick(io.orchard.protocol.message.ClientMessage message) {
        sim.beginTick();
        sim.received(agents, message);
        sim.endTick();
    }

    @ParameterizedTest(name = "to x = {0}")
    @ValueSource(doubles = {1e300, -1e300, Double.MAX_VALUE, 51, -1e-300 - 60})
    void aMoveFarOutsideTheWorldIsRejectedAndTheAgentStays(double x) {
        tick(new MoveMessage(++seq, "Guppy", Vec3.ZERO, new Vec3(x, 0, x)));
        ActionResultMessage result = agents.last(ActionResultMessage.class);
        assertThat(result.outcome()).isEqualTo(Outcome.REJECTED);
        assertThat(result.reason()).startsWith("path ");
        assertThat(sim.agents.get("Guppy").position).isEqualTo(Vec3.ZERO);
    }

    @Test
    void aHugeTurnEndsAsAnOrdinaryHeading() {
        tick(new SetRotationMessage(++seq, "Guppy", Rotation.heading(1e300)));
        double heading = sim.agents.get("Guppy").heading;
        assertThat(heading).isFinite().isGreaterThan(-Math.PI).isLessThanOrEqualTo(Math.PI);
    }

    @Test
    void aGiantBodyIsCutToTheLimits() {
        Body giant = new Body(1e300, 1e300, 1e300, new Gripper("hands", 1e300, 0, 1e300), new Sight(1e300, 2 * Math.PI));
        sim.received(agents, new RegisterMessage(++seq, "Giant", giant, null));
        sim.applyNow();
        Body body = agents.last(RegisteredMessage.class).body();
        assertThat(body.radius()).isEqualTo(2);
        assertThat(body.maxSpeed()).isEqualTo(20);
        assertThat(body.gripper().reach()).isEqualTo(2.5);
        assertThat(body.sight().range()).isEqualTo(60);
    }

    @Test
    void aGraspOfAFruitOutOfReachOrNotThereFailsAndTakesNothing() {
        tick(new GraspRequestMessage(++seq, "Guppy", "F5"));
        assertThat(agents.last(GraspResultMessage.class).success()).isFalse();
        tick(new GraspRequestMessage(++seq, "Guppy", "F404"));
        assertThat(agents.last(GraspResultMessage.class).reason()).contains("not in the world");
        assertThat(sim.fruitLeft()).isEqualTo(4);
    }

    @Test
    void aConnectionMayDriveEightAgentsAndNoMore() {
        for (int i = 1; i <= 8; i++) {
            sim.received(agents, new RegisterMessage(++seq, "A" + i, TestWorlds.BODY, null));
        }
        sim.applyNow();
        assertThat(sim.agentNames()).hasSize(8);
        assertThat(agents.last(ErrorMessage.class).code()).isEqualTo(ErrorCode.TOO_MANY_AGENTS);
        assertThat(agents.last(ErrorMessage.class).text()).contains("at most 8 agents");
    }

    @Test
    void aGameTakesOnlySoManyDifferentNamesSoThatRegistrationsCannotFillTheMemory() {
        sim.registrations.maxNames = 3;
        for (int i = 0; i < 5; i++) {
            FakeSession churn = new FakeSession(10 + i, Role.AGENT);
            sim.connected(churn);
            sim.received(churn, new RegisterMessage(++seq, "Churn" + i, TestWorlds.BODY, null));
            sim.disconnected(churn, "connection closed");
        }
        sim.applyNow();
        assertThat(sim.ranking()).hasSize(3);
    }
}
