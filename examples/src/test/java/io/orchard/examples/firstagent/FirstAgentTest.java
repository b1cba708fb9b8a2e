package io.orchard.examples.firstagent;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.examples.Orchard;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The tutorial's agent collects fruit, and stays as short as the tutorial says. */
class FirstAgentTest {

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
    void theFirstAgentIsUnderFortyLinesIncludingItsImports() throws Exception {
        Path source = Path.of("src/main/java/io/orchard/examples/firstagent/FirstAgent.java");

        // The count alone on failure: the lines themselves are in the reader's editor already.
        assertThat(Files.readAllLines(source, StandardCharsets.UTF_8).size())
                .as("lines in %s, which the README and the tutorial say is under 40", source.getFileName())
                .isLessThan(40);
    }
}
