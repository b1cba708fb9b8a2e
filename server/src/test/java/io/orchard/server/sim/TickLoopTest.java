package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
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
    private final List<MissedTurn> missed = new ArrayList<>();
    private Simulation sim;
    private TickLoop loop;

    /** A game of 20 ticks a second (50 ms each) with a lockstep deadline of one second. */
    private void game(ClockMode mode, int waitFor) {
        listeners.add(new GameListener() {
            @Override
            public void turnMissed(MissedTurn turn) {
                missed.add(turn);
            }
        });
        sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, mode, 30, waitFor, Duration.ofSeconds(1), 8,
                BodyLimits.DEFAULT), 7, "test", Recorder.NONE, listeners, (name, radius) -> Vec3.ground(0, 0));
        loop = new TickLoop(sim, clock);
        sim.connected(client);
    }

    /** Registers Guppy and ends its setup turn, which starts the game. */
    private void running(ClockMode mode) throws InterruptedException {
        game(mode, 0);
        sim.received(client, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        sim.received(client, new EndTurnMessage(2, 0));
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
    void aRealtimeTicksEndGoesOutWithTheNextTicksStart() throws InterruptedException {
        running(ClockMode.REALTIME);
        sim.received(client, new PerceptionRequestMessage(3, "Guppy", 0));
        loop.step();
        // The request's result waits for the next tick's start, which follows at once.
        ServerMessage result = client.last(ActionResultMessage.class);
        assertThat(client.received.indexOf(result)).isGreaterThanOrEqualTo(client.flushed);
        loop.step();
        assertThat(client.flushed).isEqualTo(client.received.size());
        assertThat(client.received.indexOf(result)).isLessThan(client.received.indexOf(client.last(TickMessage.class)));
        loop.stop();
        loop.run();
        assertThat(client.flushed).isEqualTo(client.received.size());
    }

    @Test
    void aLockstepTicksEndGoesOutWithTheNextTicksStart() throws InterruptedException {
        running(ClockMode.LOCKSTEP);
        sim.received(client, new PerceptionRequestMessage(3, "Guppy", 0));
        sim.received(client, new EndTurnMessage(4, 0));
        loop.step();
        // Its result waits for tick 1's start, which follows at once: one write, one wake-up of the client.
        ServerMessage result = client.last(ActionResultMessage.class);
        assertThat(client.received.indexOf(result)).isGreaterThanOrEqualTo(client.flushed);
        sim.received(client, new EndTurnMessage(5, 1));
        loop.step();
        assertThat(client.received.indexOf(result)).isLessThan(client.flushed)
                .isLessThan(client.received.indexOf(client.last(TickMessage.class)));
        assertThat(client.all(TickMessage.class)).extracting(TickMessage::tick).containsExactly(0L, 1L);
    }

    @Test
    void whatALockstepTicksEndLeftGoesOutWhenTheGameIsOver() throws InterruptedException {
        running(ClockMode.LOCKSTEP);
        sim.received(client, new PerceptionRequestMessage(3, "Guppy", 0));
        sim.received(client, new EndTurnMessage(4, 0));
        loop.step();
        sim.end("stopped");
        loop.step();
        assertThat(sim.phase()).isEqualTo(Phase.OVER);
        assertThat(client.flushed).isEqualTo(client.received.size());
    }

    @Test
    void whatARealtimeTicksEndLeftGoesOutWhenTheGamePauses() throws InterruptedException {
        running(ClockMode.REALTIME);
        sim.received(client, new PerceptionRequestMessage(3, "Guppy", 0));
        loop.step();
        sim.togglePause();
        loop.step();
        assertThat(sim.phase()).isEqualTo(Phase.PAUSED);
        assertThat(client.flushed).isEqualTo(client.received.size());
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
    void aLockstepTickWithNoAgentsClientToWaitForEndsAtOnce() throws InterruptedException {
        running(ClockMode.LOCKSTEP);
        sim.received(client, new EndTurnMessage(10, 0));
        loop.step();
        sim.disconnected(client, "gone");
        steps(4); // tick 1 ends as the client leaves; ticks 2 to 4 have no one to wait for
        assertThat(sim.tick()).isEqualTo(5);
        assertThat(clock.millis()).isZero();
        sim.end("stopped");
        loop.step();
        assertThat(sim.phase()).isEqualTo(Phase.OVER);
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

    @Test
    void aLockstepGameStartsWhenItsAgentsHaveEndedTheirSetupTurns() throws InterruptedException {
        game(ClockMode.LOCKSTEP, 0);
        sim.received(client, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        loop.step();
        assertThat(sim.phase()).as("registered, its setup not over").isEqualTo(Phase.WAITING);
        sim.received(client, new PerceptionRequestMessage(2, "Guppy", 1));
        sim.received(client, new EndTurnMessage(3, 0));
        loop.step();
        assertThat(sim.phase()).isEqualTo(Phase.RUNNING);
        assertThat(sim.tick()).as("the setup was applied before tick 0").isZero();
        assertThat(missed).isEmpty();
        assertThat(clock.millis()).isZero();
    }

    @Test
    void aLockstepGameStartsWithoutASetupTurnThatMissesTheDeadlineAndRecordsIt() throws InterruptedException {
        game(ClockMode.LOCKSTEP, 0);
        sim.received(client, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        loop.step();
        while (sim.phase() == Phase.WAITING) {
            loop.step(); // nothing comes
        }
        assertThat(clock.millis()).isEqualTo(1000);
        assertThat(missed).containsExactly(new MissedTurn(0, List.of("Guppy"), MissedTurn.Kind.SETUP));
    }

    @Test
    void aClientThatMissesThreeTurnsInARowIsNoLongerWaitedForUntilItIsInTimeAgain() throws InterruptedException {
        game(ClockMode.LOCKSTEP, 2);
        FakeSession slow = new FakeSession(2, Role.AGENT);
        sim.connected(slow);
        sim.received(client, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        sim.received(slow, new RegisterMessage(1, "Sloth", TestWorlds.BODY, null));
        sim.received(client, new EndTurnMessage(2, 0));
        sim.received(slow, new EndTurnMessage(2, 0));
        loop.step();
        assertThat(sim.phase()).isEqualTo(Phase.RUNNING);

        for (long tick = 0; tick < 5; tick++) { // Sloth says nothing
            sim.received(client, new EndTurnMessage(10 + tick, tick));
            loop.step();
        }
        assertThat(sim.tick()).isEqualTo(5);
        assertThat(clock.millis()).as("three ticks waited for Sloth until the deadline, then none").isEqualTo(3000);
        assertThat(missed).extracting(MissedTurn::tick, MissedTurn::kind).containsExactly(
                org.assertj.core.groups.Tuple.tuple(0L, MissedTurn.Kind.DEADLINE),
                org.assertj.core.groups.Tuple.tuple(1L, MissedTurn.Kind.DEADLINE),
                org.assertj.core.groups.Tuple.tuple(2L, MissedTurn.Kind.DEADLINE),
                org.assertj.core.groups.Tuple.tuple(3L, MissedTurn.Kind.LATE),
                org.assertj.core.groups.Tuple.tuple(4L, MissedTurn.Kind.LATE));
        assertThat(missed).allSatisfy(m -> assertThat(m.agents()).containsExactly("Sloth"));

        sim.received(slow, new EndTurnMessage(20, 5)); // in time again
        sim.received(client, new EndTurnMessage(21, 5));
        loop.step();
        sim.received(client, new EndTurnMessage(22, 6));
        loop.step(); // tick 6: Sloth is waited for again
        assertThat(clock.millis()).isEqualTo(4000);
        assertThat(missed).hasSize(6).last().extracting(MissedTurn::tick, MissedTurn::kind)
                .containsExactly(6L, MissedTurn.Kind.DEADLINE);
    }
}
