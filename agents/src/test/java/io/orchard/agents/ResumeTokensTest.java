package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.GameOverMessage;
import io.orchard.server.WorldServer;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** An agent that keeps its resume token in a file comes back with it when it is run again. */
class ResumeTokensTest {

    @TempDir
    Path dir;

    private static CompletableFuture<GameOverMessage> play(AgentController agent, int port) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                return agent.run("127.0.0.1", port);
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException(e);
            }
        });
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as(what).isLessThan(deadline);
            Thread.sleep(20);
        }
    }

    private static String tokenOf(Path file, String agent) {
        try {
            return new ResumeTokenFile(file).read().get(agent);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void anAgentRunAgainAfterItsConnectionDroppedComesBackWithTheTokenItKeptAndNoOneElseTakesItsName()
            throws Exception {
        Path file = dir.resolve("resume-tokens");
        try (WorldServer server = WorldServer.builder().port(0).seed(7).timeLimit(300).start()) {
            AgentControllerTest.Recorder first = new AgentControllerTest.Recorder("Keeper");
            first.keepResumeTokensIn(file);
            CompletableFuture<GameOverMessage> firstRun = play(first, server.port());
            await("Keeper's token in the file", () -> tokenOf(file, "Keeper") != null);
            String token = tokenOf(file, "Keeper");
            assertThat(token).hasSize(32);
            await("Keeper's first ticks", () -> first.ticks.size() > 5);
            first.stop();
            assertThat(firstRun.get(30, TimeUnit.SECONDS)).isNull();
            await("Keeper gone", () -> server.status().contains("agents []"));

            AgentControllerTest.Recorder squatter = new AgentControllerTest.Recorder("Keeper");
            assertThatThrownBy(() -> squatter.run("127.0.0.1", server.port())).isInstanceOf(IOException.class)
                    .hasMessageContaining("name_in_use: agent 'Keeper' left").hasMessageContaining("frees up in");

            AgentControllerTest.Recorder again = new AgentControllerTest.Recorder("Keeper");
            again.keepResumeTokensIn(file);
            CompletableFuture<GameOverMessage> secondRun = play(again, server.port());
            await("Keeper back and playing", () -> again.ticks.size() > 5);
            assertThat(server.status()).contains("agents [Keeper]");
            // A new agent would have had a new token written: the same one means the agent came back.
            assertThat(tokenOf(file, "Keeper")).isEqualTo(token);

            server.endGame("enough");
            assertThat(secondRun.get(30, TimeUnit.SECONDS).reason()).isEqualTo("enough");
            assertThat(tokenOf(file, "Keeper")).as("a token of a game that is over").isNull();
        }
    }

    @Test
    void aTokenOfAnotherGameIsIgnoredByTheServerAndReplacedByTheNewOne() throws Exception {
        Path file = dir.resolve("resume-tokens");
        new ResumeTokenFile(file).update(tokens -> tokens.put("Keeper", "0123456789abcdef0123456789abcdef"));
        try (WorldServer server = WorldServer.builder().port(0).seed(7).timeLimit(300).start()) {
            AgentControllerTest.Recorder agent = new AgentControllerTest.Recorder("Keeper");
            agent.keepResumeTokensIn(file);
            CompletableFuture<GameOverMessage> run = play(agent, server.port());
            await("Keeper's new token in the file",
                    () -> !"0123456789abcdef0123456789abcdef".equals(tokenOf(file, "Keeper")));
            assertThat(tokenOf(file, "Keeper")).hasSize(32);
            agent.stop();
            run.get(30, TimeUnit.SECONDS);
        }
    }

    @Test
    void aFileThatCannotBeWrittenCostsOnlyTheComingBack() throws Exception {
        Path notAFolder = Files.writeString(dir.resolve("plain-file"), "in the way");
        try (WorldServer server = WorldServer.builder().port(0).seed(7).timeLimit(1).start()) {
            AgentControllerTest.Recorder agent = new AgentControllerTest.Recorder("Keeper");
            agent.keepResumeTokensIn(notAFolder.resolve("resume-tokens"));
            assertThat(play(agent, server.port()).get(60, TimeUnit.SECONDS).reason()).isEqualTo("time limit reached");
        }
    }
}
