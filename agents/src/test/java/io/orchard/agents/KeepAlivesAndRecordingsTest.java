package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A keep-alive goes when the wall clock says so, so it must leave no trace in a lockstep game's
 * recording: the same game, once with an agent that waits long enough for its partner to send
 * keep-alives and once with no wait, is recorded byte for byte alike. (Keep-alives once took
 * sequence numbers, and every message after one was recorded with a number one higher.)
 */
class KeepAlivesAndRecordingsTest {

    @TempDir
    Path dir;

    /** An agent with the default behaviour, whose keep-alives come after a short silence. */
    static final class Forager extends AgentController {
        Forager(String name) {
            super(name);
            keepAliveEvery(Duration.ofMillis(50));
        }

        @Override
        protected AgentBody body() {
            return AgentBody.builder().radius(0.4).speed(8).gripper("hands", 0.7, 0, 2).sight(35, 2 * Math.PI)
                    .build();
        }
    }

    /** Plays a game of two agents, the second connecting {@code late} after the first is in the world. */
    private byte[] play(String name, Duration late) throws Exception {
        Path recording = dir.resolve(name + ".ndjson");
        CompletableFuture<String> joined = new CompletableFuture<>();
        ExecutorService threads = Executors.newFixedThreadPool(2);
        try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(3)
                .waitFor(2).record(recording).listener(new GameListener() {
                    @Override
                    public void agentJoined(String agent) {
                        joined.complete(agent);
                    }
                }).start()) {
            Future<?> first = threads.submit(() -> new Forager("Ann").run("127.0.0.1", server.port()));
            assertThat(joined.get(30, TimeUnit.SECONDS)).isEqualTo("Ann");
            Thread.sleep(late.toMillis());
            Future<?> second = threads.submit(() -> new Forager("Bob").run("127.0.0.1", server.port()));
            first.get(2, TimeUnit.MINUTES);
            second.get(2, TimeUnit.MINUTES);
            server.gameOver().get(1, TimeUnit.MINUTES);
        } finally {
            threads.shutdownNow();
        }
        return Files.readAllBytes(recording);
    }

    @Test
    void keepAlivesSentWhileWaitingForTheGameLeaveItsRecordingAsItWouldBe() throws Exception {
        byte[] waited = play("waited", Duration.ofMillis(600));
        byte[] straight = play("straight", Duration.ZERO);
        assertThat(new String(waited, java.nio.charset.StandardCharsets.UTF_8)).as("a real game")
                .contains("\"type\":\"GameOver\"");
        assertThat(waited).as("the game in which Ann waited and said she was still here, byte for byte")
                .isEqualTo(straight);
    }
}
