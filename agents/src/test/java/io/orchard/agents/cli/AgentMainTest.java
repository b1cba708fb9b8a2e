package io.orchard.agents.cli;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class AgentMainTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private static InputStream console(String text) {
        return new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8));
    }

    private PrintStream print(ByteArrayOutputStream bytes) {
        return new PrintStream(bytes, true, StandardCharsets.UTF_8);
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    @Nested
    class CommandLines {

        @Test
        void theHelpListsEveryOption() throws Exception {
            assertThat(AgentMain.agentHelp()).contains("Usage: orchard agent [OPTIONS]", "--type=TYPE",
                    "dwarf, robot, bunny, guppy, roadrunner", "--name=NAME", "--host=HOST", "--port=N", "--resume-tokens=FILE",
                    "--language=CODE", "--language-model=URL", "--language-model-name=MODEL",
                    "--language-model-timeout=SECONDS",
                    "(default: " + Path.of(System.getProperty("user.home"), ".orchard", "resume-tokens"), "--help");
            assertThat(AgentMain.agentHelp()).contains("--next-games");
            assertThat(AgentMain.agentsHelp()).contains("Usage: orchard agents [OPTIONS]", "--host=HOST", "--port=N",
                    "--resume-tokens=FILE", "--next-games", "--language=CODE")
                    .doesNotContain("--type");
            assertThat(AgentMain.agent(List.of("--help"), console(""), print(out), print(err))).isZero();
            assertThat(out()).contains("Usage: orchard agent");
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = '|', textBlock = """
            no type         | agent  |                            | orchard agent: missing required option '--type' (expected one of dwarf, robot, bunny, guppy, roadrunner)
            unknown type    | agent  | --type unicorn             | orchard agent: invalid value for option '--type': no agent type 'unicorn'; expected one of dwarf, robot, bunny, guppy, roadrunner
            name not a name | agent  | --type bunny --name 9lives | orchard agent: invalid value for option '--name': an agent's name must be a letter followed by up to 31 letters, digits, '_' or '-', was '9lives'
            port zero       | agent  | --type bunny --port 0      | orchard agent: invalid value for option '--port': '0' is out of range (expected a port 1-65535)
            port not number | agent  | --type bunny --port seven  | orchard agent: invalid value for option '--port': 'seven' is not an integer (expected a port 1-65535)
            type of agents  | agents | --type bunny               | orchard agents: unknown options: '--type', 'bunny'
            model no name   | agent  | --type bunny --language-model http://localhost:11434/v1 | orchard agent: --language-model needs --language-model-name MODEL, the model to ask
            name no model   | agents | --language-model-name llama3.2 | orchard agents: --language-model-name needs --language-model URL
            model bad url   | agent  | --type bunny --language-model localhost:11434 --language-model-name m | orchard agent: invalid value for option '--language-model': 'localhost:11434' (expected an http or https address such as http://localhost:11434/v1)
            model timeout   | agents | --language-model http://h/v1 --language-model-name m --language-model-timeout 0 | orchard agents: invalid value for option '--language-model-timeout': '0.0' (expected seconds, more than 0 and at most 600)
            language        | agent  | --type bunny --language fr | orchard agent: invalid value for option '--language': 'fr' (expected en or de)
            """)
        void wrongCommandLinesAreNamedAndExitWithTwo(String name, String command, String line, String message) {
            List<String> args = line == null ? List.of() : List.of(line.split(" "));
            int status = command.equals("agent") ? AgentMain.agent(args, console(""), print(out), print(err))
                    : AgentMain.agents(args, console(""), print(out), print(err));

            assertThat(status).isEqualTo(2);
            assertThat(err.toString(StandardCharsets.UTF_8)).contains(message, "Run ./" + message.split(":")[0]
                    + " --help for its options.");
        }

        @Test
        void noServerIsAFailureThatSaysSo() throws Exception {
            int status = AgentMain.agent(List.of("--type", "bunny", "--port", "1"), console(""), print(out), print(err));

            assertThat(status).isEqualTo(1);
            assertThat(err.toString(StandardCharsets.UTF_8))
                    .isEqualTo("orchard agent: no server is listening at localhost:1 (connection refused)"
                            + System.lineSeparator());
            assertThat(out()).contains("Bunny (bunny) is connecting to localhost:1").doesNotContain("joins the game");
        }
    }

    @Nested
    class Playing {

        /** Where the agents keep their tokens, instead of the home folder. */
        @TempDir
        Path tokens;

        @Test
        void oneAgentTakesConsoleLinesAsInstructionsAndPrintsWhatItSays() throws Exception {
            try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(20)
                    .start()) {
                int status = AgentMain.agent(List.of("--type", "guppy", "--name", "Gup", "--host", "127.0.0.1",
                        "--port", String.valueOf(server.port()), "--resume-tokens", tokens.resolve("resume-tokens").toString()),
                        console("explore\n\ndance\n"), print(out), print(err));

                assertThat(status).isZero();
            }
            assertThat(out()).contains("Gup (guppy) is connecting to 127.0.0.1:", "Gup: Exploring.", "Gup: I didn't understand 'dance'",
                    "Game over (time limit reached). Ranking:", "1. Gup", "Gup: ");
        }

        @Test
        void allFiveTakeInstructionsAddressedByName() throws Exception {
            try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(10)
                    .waitFor(5).start()) {
                int status = AgentMain.agents(List.of("--host", "127.0.0.1", "--port", String.valueOf(server.port()),
                        "--resume-tokens", tokens.resolve("resume-tokens").toString()),
                        console("Dwarf: stop\nroadrunner carry on\nGuppy, turn left\nnobody: hello\n"), print(out), print(err));

                assertThat(status).isZero();
            }
            assertThat(out()).contains("Dwarf, Robot, Bunny, Guppy, Roadrunner are connecting to 127.0.0.1:", "Dwarf: Stopping.",
                    "Roadrunner: Carrying on by myself.", "Guppy: Turning left.", "Start the line with the agent's name",
                    "Game over", "Bunny: ");
        }

        @Test
        void withNextGamesAllFiveComeBackForEachGameTheOperatorRestartsAndLeaveWithTheServer() throws Exception {
            CompletableFuture<Integer> status;
            List<Score> second;
            try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(1)
                    .waitFor(5).start()) {
                status = CompletableFuture.supplyAsync(() -> AgentMain.agents(List.of("--host", "127.0.0.1", "--port",
                        String.valueOf(server.port()), "--resume-tokens", tokens.resolve("resume-tokens").toString(),
                        "--next-games"), console(""), print(out), print(err)));
                List<Score> first = server.gameOver().get(60, TimeUnit.SECONDS);
                assertThat(first).hasSize(5);

                server.restart(7);
                second = server.gameOver().get(60, TimeUnit.SECONDS);
                assertThat(status).as("the agents stay for the next game").isNotDone();
            }
            assertThat(status.get(30, TimeUnit.SECONDS)).as(err.toString(StandardCharsets.UTF_8)).isZero();
            assertThat(second).extracting(Score::agent)
                    .containsExactlyInAnyOrder("Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner");
            assertThat(out()).contains("Game over (time limit reached). Ranking:");
        }
    }
}
