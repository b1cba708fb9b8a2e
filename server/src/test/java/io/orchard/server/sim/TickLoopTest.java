package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The tick loop stepped on a fake clock: schedules, lateness and lockstep deadlines with no real time. */
class TickLoopTest {

    private final FakeLoopClock clock = new FakeLoopClock();
    private final FakeSession client = new FakeSession(1, Role.AGENT);
    private final List<GameListener> listeners = new ArrayList<>();
    private Simulation sim;
    private TickLoop loop;

    /** A game of 20 ticks a second (50 ms each) with a lockstep deadline of one second. */
    private void game(ClockMode mode, int waitFor) {
        sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, mode, 30, waitFor, Duration.ofSeconds(1), 8,
                BodyLimits.DEFAULT), 7, "test", Recorder.NONE, listeners, (name, radius) -> Vec3.ground(0, 0));
        loop = new TickLoop(sim, clock);
        sim.connected(client);
    }

    /** Registers Guppy, which starts the game. */
    private void running(ClockMode mode) throws InterruptedException {
        game(mode, 0);
        sim.received(client, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        loop.step();
        assertThat(sim.phase()).isEqualTo(Phase.RUNNING);
    }

    private void steps(int count) throws InterruptedException {
        for (int i = 0; i < count; i++) {
            loop.step();
        }
    }

    @Test
    void whileTheGameWaitsWhatClientsSendIsAppliedAsItComes() throws InterruptedException {
        game(ClockMode.REALTIME, 2);
        sim.received(client, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        loop.step();
        assertThat(sim.agentNames()).containsExactly("Guppy");
        assertThat(sim.phase()).isEqualTo(Phase.WAITING);
        assertThat(clock.millis()).isZero();
        loop.step(); // nothing more came: a short wait, and no tick
        assertThat(clock.millis()).isEqualTo(50);
        assertThat(sim.tick()).isZero();
    }

    @Test
    void realtimeTicksComeDueOnAFixedSchedule() throws InterruptedException {
        running(ClockMode.REALTIME);
        steps(20);
        assertThat(sim.tick()).isEqualTo(20);
        assertThat(clock.millis()).isEqualTo(1000);
        assertThat(loop.stats().ticks()).isEqualTo(20);
        assertThat(loop.stats().lateTicks()).isZero();
    }

    @Test
    void aClockThatFellFarBehindStartsANewScheduleInsteadOfRushing() throws InterruptedException {
        listeners.add(new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                if (tick == 2) {
                    clock.advance(1000); // a tick that works a whole second
                }
            }
        });
        running(ClockMode.REALTIME);
        steps(3);
        assertThat(clock.millis()).isEqualTo(150 + 1000);
        loop.step(); // late, so at once
        assertThat(clock.millis()).isEqualTo(1150);
        loop.step(); // a tick after the late one, not the 19 ticks it missed at once
        assertThat(clock.millis()).isEqualTo(1200);
        assertThat(loop.stats().lateTicks()).isEqualTo(1);
        assertThat(loop.stats().max()).isEqualTo(Duration.ofSeconds(1));
    }

    @Test
    void aLockstepTickEndsAsSoonAsEveryAgentsClientEndedItsTurn() throws InterruptedException {
        running(ClockMode.LOCKSTEP);
        for (long tick = 0; tick < 5; tick++) {
            sim.received(client, new EndTurnMessage(10 + tick, tick));
            loop.step();
        }
        assertThat(sim.tick()).isEqualTo(5);
        assertThat(clock.millis()).isZero();
    }

    @Test
    void aLockstepTickWaitsForAClientThatDoesNotEndItsTurnUntilTheDeadline() throws InterruptedException {
        running(ClockMode.LOCKSTEP);
        sim.received(client, new EndTurnMessage(10, 0));
        loop.step();
        loop.step(); // no EndTurn for tick 1
        assertThat(sim.tick()).isEqualTo(2);
        assertThat(clock.millis()).isEqualTo(1000);
    }

    @Test
    void anEndTurnForAnEarlierTickDoesNotEndTheTick() throws InterruptedException {
        running(ClockMode.LOCKSTEP);
        sim.received(client, new EndTurnMessage(10, 0));
        loop.step();
        sim.received(client, new EndTurnMessage(11, 0)); // late, for tick 0
        loop.step();
        assertThat(sim.tick()).isEqualTo(2);
        assertThat(clock.millis()).isEqualTo(1000);
    }
}
