package io.orchard.examples.firstagent;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.examples.Orchard;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The tutorial's agent collects fruit, and stays as short as the tutorial says. */
class FirstAgentTest {

    @TempDir
    Path dir;

    @Test
    void theFirstAgentCollectsFruitInALockstepGame() throws Exception {
        try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(60)
                .start()) {
            GameOverMessage over = new FirstAgent("Pippin").run("127.0.0.1", server.port());

            List<Score> ranking = over.ranking();
            assertThat(ranking).singleElement().satisfies(score -> {
                assertThat(score.agent()).isEqualTo("Pippin");
                assertThat(score.fruit()).isGreaterThanOrEqualTo(1);
            });
        }
    }

    @Test
    void theCommandWithoutAServerFailsSayingToStartOne() throws Exception {
        int port;
        try (ServerSocket free = new ServerSocket(0)) {
            port = free.getLocalPort(); // closed again: nothing listens there
        }
        ByteArrayOutputStream err = new ByteArrayOutputStream();

        int status = Orchard.run(new String[] {"first-agent", "--port", String.valueOf(port)},
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));

        assertThat(status).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo("orchard first-agent: no server is listening at localhost:"
                + port + " (connection refused); start one first, for example with ./orchard server"
                + System.lineSeparator());
    }

    @Test
    void theCommandKeepsItsResumeTokenInTheFileItIsGivenWhileTheGameLasts() throws Exception {
        Path tokens = dir.resolve("orchard").resolve("resume-tokens");
        try (WorldServer server = WorldServer.builder().port(0).seed(1998).timeLimit(300).start()) {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            CompletableFuture<Integer> status = CompletableFuture.supplyAsync(() -> Orchard.run(new String[] {
                "first-agent", "--port", String.valueOf(server.port()), "--resume-tokens", tokens.toString()},
                    new PrintStream(out, true, StandardCharsets.UTF_8),
                    new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8)));

            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!tokenLine(tokens) && System.nanoTime() < deadline) {
                Thread.sleep(50);
            }
            assertThat(tokenLine(tokens)).as("a line for FirstAgent in %s", tokens).isTrue();
            if (FileSystems.getDefault().supportedFileAttributeViews().contains("posix")) {
                assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(tokens))).isEqualTo("rw-------");
            }

            server.endGame("enough");
            assertThat(status.get(30, TimeUnit.SECONDS)).isZero();
            assertThat(tokenLine(tokens)).as("a token of a game that is over").isFalse();
            assertThat(out.toString(StandardCharsets.UTF_8)).contains("FirstAgent");
        }
    }

    private static boolean tokenLine(Path tokens) throws IOException {
        return Files.exists(tokens)
                && Files.readAllLines(tokens, StandardCharsets.UTF_8).stream().anyMatch(l -> l.startsWith("FirstAgent "));
    }

    @Test
    void theFirstAgentIsUnderFortyLinesIncludingItsImports() throws Exception {
        Path source = Path.of("src/main/java/io/orchard/examples/firstagent/FirstAgent.java");

        // The count alone on failure: the lines themselves are in the reader's editor already.
        assertThat(Files.readAllLines(source, StandardCharsets.UTF_8).size())
                .as("lines in %s, which the README and the tutorial say is under 40", source.getFileName())
                .isLessThan(40);
    }
}
