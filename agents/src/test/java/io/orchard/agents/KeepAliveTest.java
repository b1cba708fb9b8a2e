package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import io.orchard.server.net.NetLimits;
import io.orchard.server.sim.GameListener;
import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A controller told to wait has nothing to say, and says "still here" instead: in a realtime game
 * on a server that closes a connection after 1 s of silence, it keeps its connection as long as
 * it waits; without keep-alives the same agent is closed for its silence.
 */
class KeepAliveTest {

    private static final Duration IDLE = Duration.ofSeconds(1);

    private final List<String> left = new CopyOnWriteArrayList<>();
    private final CompletableFuture<String> joined = new CompletableFuture<>();
    private WorldServer server;

    /** An agent with the default behaviour, which stands still when told to wait. */
    static final class Waiter extends AgentController {
        Waiter() {
            super("Waiter");
        }

        @Override
        protected AgentBody body() {
            return AgentBody.builder().radius(0.4).speed(8).gripper("hands", 0.7, 0, 2).sight(35, 2 * Math.PI)
                    .build();
        }
    }

    @BeforeEach
    void startAServerWithAShortIdleRule() throws IOException {
        server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.REALTIME).timeLimit(600)
                .limits(new NetLimits(2_000, 4_000, IDLE, Duration.ofSeconds(10), 16L << 20))
                .listener(new GameListener() {
                    @Override
                    public void agentJoined(String agent) {
                        joined.complete(agent);
                    }

                    @Override
                    public void agentLeft(String agent, String reason) {
                        left.add(agent + ": " + reason);
                    }
                }).start();
    }

    @AfterEach
    void stopTheServer() {
        server.close();
    }

    /** Runs the agent on a thread of its own, tells it to wait once it is in the world, and lets it wait. */
    private CompletableFuture<GameOverMessage> waitInTheWorld(Waiter waiter, Duration wait) throws Exception {
        CompletableFuture<GameOverMessage> run = CompletableFuture.supplyAsync(() -> {
            try {
                return waiter.run("127.0.0.1", server.port());
            } catch (IOException e) {
                throw new IllegalStateException(e.getMessage(), e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException(e);
            }
        });
        assertThat(joined.get(30, TimeUnit.SECONDS)).isEqualTo("Waiter");
        waiter.instruct("wait here");
        Thread.sleep(wait.toMillis());
        return run;
    }

    @Test
    void aControllerToldToWaitIsNotClosedForItsSilence() throws Exception {
        Waiter waiter = new Waiter();
        waiter.keepAliveEvery(Duration.ofMillis(250));

        CompletableFuture<GameOverMessage> run = waitInTheWorld(waiter, IDLE.multipliedBy(4));

        assertThat(run).as("the agent's game after four times the idle rule").isNotDone();
        assertThat(left).isEmpty();
        assertThat(server.status()).contains("Waiter");
        waiter.stop();
        assertThat(run.get(10, TimeUnit.SECONDS)).as("run after stop").isNull();
    }

    @Test
    void withoutKeepAlivesTheSameControllerIsClosedForItsSilence() throws Exception {
        Waiter waiter = new Waiter();
        waiter.keepAliveEvery(Duration.ofHours(1));

        CompletableFuture<GameOverMessage> run = waitInTheWorld(waiter, IDLE.multipliedBy(4));

        assertThatThrownBy(() -> run.get(10, TimeUnit.SECONDS)).isInstanceOf(ExecutionException.class)
                .hasMessageContaining("the server closed the connection of Waiter");
        assertThat(left).singleElement().asString().startsWith("Waiter");
    }
}
