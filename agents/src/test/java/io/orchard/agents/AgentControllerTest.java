package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;


class AgentControllerTest {

    /** An agent that keeps the default autonomy and notes when it is asked to decide. */
    static final class Recorder extends AgentController {
        final List<long[]> decisions = new ArrayList<>();
        final List<Long> ticks = new ArrayList<>();
        private final AgentBody body;

        Recorder(String name, AgentBody body) {
            super(name);
            this.body = body;
        }

        Recorder(String name) {
            this(name, AgentBody.builder().radius(0.4).speed(8).gripper("hands", 0.7, 0, 2).build());
        }

        @Override
        protected AgentBody body() {
            return body;
        }

        @Override
        protected void onTick(long tickNumber, double seconds) {
            ticks.add(tickNumber);
        }

        @Override
        protected void decide(Perception perception) {
            decisions.add(new long[] {tick(), perception.tick()});
            super.decide(perception);
        }
    }

    @Test
    void inLockstepEveryTickIsDecidedOnItsOwnPerceptionAndItsTurnEnded() throws Exception {
        Recorder agent = new Recorder("Lockstep");
        long start = System.nanoTime();
        try (WorldServer server = WorldServer.builder().port(0).seed(7).clock(ClockMode.LOCKSTEP).timeLimit(10)
                .lockstepDeadline(Duration.ofSeconds(30)).start()) {
            agent.run("127.0.0.1", server.port());
        }
        double seconds = (System.nanoTime() - start) / 1e9;

        // Had a turn been left open, the server would have waited 30 s for it.
        assertThat(seconds).isLessThan(25);
        assertThat(agent.ticks).hasSize(200).startsWith(0L, 1L, 2L).endsWith(199L);
        assertThat(agent.decisions).allSatisfy(d -> assertThat(d[1]).isEqualTo(d[0]));
        assertThat(agent.decisions).hasSizeGreaterThanOrEqualTo(197); // every tick once perceptions come
        assertThat(agent.stats().movesSent()).isPositive();
        assertThat(agent.stats().movesRejected()).isZero();
    }

    @Test
    void anAgentThatPerceivesEveryFifthTickDecidesThenAndStillEndsEveryTurn() throws Exception {
        Recorder agent = new Recorder("Sparse", AgentBody.builder().perceptionEvery(5).build());
        long start = System.nanoTime();
        try (WorldServer server = WorldServer.builder().port(0).seed(7).clock(ClockMode.LOCKSTEP).timeLimit(10)
                .lockstepDeadline(Duration.ofSeconds(30)).start()) {
            agent.run("127.0.0.1", server.port());
        }

        assertThat((System.nanoTime() - start) / 1e9).isLessThan(25);
        assertThat(agent.ticks).hasSize(200);
        assertThat(agent.decisions).hasSizeBetween(38, 40).allSatisfy(d -> assertThat(d[1]).isEqualTo(d[0]));
        for (int i = 1; i < agent.decisions.size(); i++) {
            assertThat(agent.decisions.get(i)[0] - agent.decisions.get(i - 1)[0]).isEqualTo(5);
        }
    }

    @Test
    void inRealtimeTheAgentActsOnEachPerceptionAsItComes() throws Exception {
        Recorder agent = new Recorder("Realtime");
        try (WorldServer server = WorldServer.builder().port(0).seed(7).clock(ClockMode.REALTIME).timeLimit(3).start()) {
            GameOverMessage over = agent.run("127.0.0.1", server.port());

            assertThat(over.reason()).isEqualTo("time limit reached");
        }
        assertThat(agent.decisions).hasSizeGreaterThan(40);
        assertThat(agent.stats().movesSent()).isPositive();
        assertThat(agent.stats().obstacleRejections()).isZero();
    }

    @Test
    void aModelMissingARegisteredJointIsRefusedBeforeTheAgentRegisters() throws Exception {
        Recorder agent = new Recorder("Pippin", AgentBody.builder().model("Pippin.x3d").joints("LeftKnee", "RightKnee")
                .walkAnimation("PippinTSWalk").build());
        List<String> joined = new CopyOnWriteArrayList<>();
        try (WorldServer server = WorldServer.builder().port(0).seed(7).clock(ClockMode.LOCKSTEP)
                .listener(new GameListener() {
                    @Override
                    public void agentJoined(String name) {
                        joined.add(name);
                    }
                }).start()) {
            assertThatThrownBy(() -> agent.run("127.0.0.1", server.port()))
                    .isInstanceOf(ModelCheckException.class)
                    .hasMessage("model Pippin.x3d cannot be registered: no joint RightKnee: the model has no node"
                            + " DEF 'RightKnee'");
        }
        assertThat(joined).isEmpty();
    }

    @Test
    void aRefusedRegistrationSaysWhy() throws Exception {
        try (WorldServer server = WorldServer.builder().port(0).seed(7).clock(ClockMode.LOCKSTEP).waitFor(2).start()) {
            Recorder first = new Recorder("Twin");
            CompletableFuture<GameOverMessage> playing = CompletableFuture.supplyAsync(() -> {
                try {
                    return first.run("127.0.0.1", server.port());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            while (first.memory() == null) {
                Thread.sleep(10);
            }

            assertThatThrownBy(() -> new Recorder("Twin").run("127.0.0.1", server.port()))
                    .isInstanceOf(java.io.IOException.class)
                    .hasMessageContaining("the server refused to register Twin: name_in_use");
            first.stop();
            assertThat(playing.get(10, TimeUnit.SECONDS)).isNull();
        }
    }

    @Test
    void instructionsFromTheConsoleAndFromOtherClientsAreCarriedOutAndAnswered() throws Exception {
        Recorder agent = new Recorder("Obedient");
        List<String> said = new CopyOnWriteArrayList<>();
        agent.addSpeechListener(said::add);
        agent.instruct("dance");
        agent.instruct("turn around");
        agent.instruct("Guppy, stop");
        try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(40)
                .start()) {
            CompletableFuture<GameOverMessage> playing = CompletableFuture.supplyAsync(() -> {
                try {
                    return agent.run("127.0.0.1", server.port());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            while (said.stream().noneMatch(s -> s.startsWith("Done: I'm facing"))) {
                Thread.sleep(10);
                assertThat(playing).isNotDone();
            }
            try (ProtocolConnection teacher = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER,
                    "teacher", message -> { })) {
                teacher.send(seq -> new InstructionMessage(seq, "Obedient", "collect coconut", "teacher"));
                playing.get(60, TimeUnit.SECONDS);
            }
        }

        Interpretation dance = new InstructionInterpreter().interpret("dance");
        assertThat(dance).isInstanceOf(Interpretation.NotUnderstood.class);
        assertThat(said).startsWith(
                ((Interpretation.NotUnderstood) dance).answer(),
                "Turning around.",
                "That was for Guppy, not for me.");
        assertThat(said.get(3)).startsWith("Done: I'm facing").endsWith("Carrying on by myself.");
        assertThat(said.get(4)).isEqualTo("Going to pick up a coconut.");
    }
}
