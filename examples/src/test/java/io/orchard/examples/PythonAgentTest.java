package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The protocol is open to any language: the Python example agent, which reads the lean form alone
 * (a perception as one LeanPerception line, no answer to an accepted move), plays a real game and scores.
 */
class PythonAgentTest {

    @TempDir
    Path dir;

    @Test
    void thePythonAgentRegistersPerceivesMovesAndCollects() throws Exception {
        Path script = Path.of("python", "orchard_agent.py").toAbsolutePath();
        assertThat(script).exists();
        try (WorldServer server = WorldServer.builder().port(0).seed(42).clock(ClockMode.LOCKSTEP).timeLimit(60)
                .start()) {
            Path log = dir.resolve("agent.log");
            Process agent = python(script, "--port", String.valueOf(server.port()), "--name", "Pyro")
                    .redirectErrorStream(true).redirectOutput(log.toFile()).start();
            try {
                List<Score> ranking = server.gameOver().get(120, TimeUnit.SECONDS);
                assertThat(agent.waitFor(20, TimeUnit.SECONDS)).as("the agent exits after game over").isTrue();
                String output = Files.readString(log, StandardCharsets.UTF_8);
                assertThat(ranking).as(output).singleElement().satisfies(score -> {
                    assertThat(score.agent()).isEqualTo("Pyro");
                    assertThat(score.fruit()).isGreaterThanOrEqualTo(1);
                });
                assertThat(output).contains("collected", "game over");
            } finally {
                agent.destroyForcibly();
            }
        }
    }

    @Test
    void thePythonAgentAndAJavaAgentPlayTheSameLockstepGameTwice() throws Exception {
        Path script = Path.of("python", "orchard_agent.py").toAbsolutePath();
        byte[] first = recordGameWithPython(script, "first.ndjson");
        byte[] second = recordGameWithPython(script, "second.ndjson");

        assertThat(new String(first, StandardCharsets.UTF_8)).doesNotContain("\"dir\":\"missed\"")
                .contains("\"client\":\"Pyro\"", "\"client\":\"Guppy\"");
        assertThat(second).as("the second recording, byte for byte").isEqualTo(first);
    }

    /** A 20-second lockstep game of the Python agent and Guppy, the Python agent connecting first. */
    private byte[] recordGameWithPython(Path script, String file) throws Exception {
        Path recording = dir.resolve(file);
        try (WorldServer server = WorldServer.builder().port(0).seed(42).clock(ClockMode.LOCKSTEP).timeLimit(20)
                .waitFor(2).lockstepDeadline(java.time.Duration.ofSeconds(20)).record(recording).start()) {
            Process agent = python(script, "--port", String.valueOf(server.port()), "--name", "Pyro")
                    .redirectErrorStream(true).redirectOutput(dir.resolve(file + ".log").toFile()).start();
            try {
                AgentController guppy = Species.GUPPY.create();
                guppy.run("127.0.0.1", server.port());
                server.gameOver().get(120, TimeUnit.SECONDS);
                assertThat(agent.waitFor(20, TimeUnit.SECONDS)).as("the agent exits after game over").isTrue();
            } finally {
                agent.destroyForcibly();
            }
        }
        return Files.readAllBytes(recording);
    }

    @Test
    void withoutAServerThePythonAgentSaysSoInOneLineAndFails() throws Exception {
        Path script = Path.of("python", "orchard_agent.py").toAbsolutePath();
        int port;
        try (java.net.ServerSocket free = new java.net.ServerSocket(0)) {
            port = free.getLocalPort(); // closed again: nothing listens there
        }
        Path log = dir.resolve("agent.log");
        Process agent = python(script, "--port", String.valueOf(port)).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        try {
            assertThat(agent.waitFor(20, TimeUnit.SECONDS)).isTrue();
            assertThat(agent.exitValue()).isEqualTo(1);
            assertThat(Files.readString(log, StandardCharsets.UTF_8)).isEqualTo("orchard_agent.py: no server is"
                    + " listening at localhost:" + port + "; start one first, for example with ./orchard server\n");
        } finally {
            agent.destroyForcibly();
        }
    }

    private static ProcessBuilder python(Path script, String... args) throws IOException {
        String python = findPython();
        List<String> command = new java.util.ArrayList<>(List.of(python, script.toString()));
        command.addAll(List.of(args));
        return new ProcessBuilder(command);
    }

    static String findPython() throws IOException {
        for (String candidate : List.of("python3", "python")) {
            try {
                Process probe = new ProcessBuilder(candidate, "--version").redirectErrorStream(true).start();
                if (probe.waitFor(10, TimeUnit.SECONDS) && probe.exitValue() == 0) {
                    return candidate;
                }
            } catch (IOException | InterruptedException e) {
                // try the next name
            }
        }
        throw new IOException("this test needs Python 3 as python3 on the PATH (.ci/run installs it)");
    }
}
