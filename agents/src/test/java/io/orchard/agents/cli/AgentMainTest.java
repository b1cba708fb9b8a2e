package io.orchard.agents.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.cli.UsageException;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

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
            assertThat(AgentMain.agentHelp()).contains("Usage: orchard agent [options]", "--type TYPE",
                    "dwarf, robot, bunny, guppy, roadrunner", "--name NAME", "--host HOST", "--port N", "--help");
            assertThat(AgentMain.agentsHelp()).contains("Usage: orchard agents [options]", "--host HOST", "--port N")
                    .doesNotContain("--type");
            assertThat(AgentMain.agent(List.of("--help"), console(""), print(out), print(err))).isZero();
            assertThat(out()).contains("Usage: orchard agent");
        }

        @Test
        void wrongCommandLinesAreNamed() {
            assertThatThrownBy(() -> AgentMain.agent(List.of(), console(""), print(out), print(err)))
                    .isInstanceOf(UsageException.class)
                    .hasMessage("--type is required: one of dwarf, robot, bunny, guppy, roadrunner");
            assertThatThrownBy(() -> AgentMain.agent(List.of("--type", "unicorn"), console(""), print(out), print(err)))
                    .hasMessage("--type: no agent type 'unicorn'; expected one of dwarf, robot, bunny, guppy, roadrunner");
            assertThatThrownBy(() -> AgentMain.agent(List.of("--type", "bunny", "--name", "two words"), console(""),
                    print(out), print(err))).hasMessageContaining("--name must be a letter");
            assertThatThrownBy(() -> AgentMain.agent(List.of("--type", "bunny", "--port", "0"), console(""), print(out),
                    print(err))).hasMessage("--port must be 1 to 65535, was 0");
            assertThatThrownBy(() -> AgentMain.agents(List.of("--type", "bunny"), console(""), print(out), print(err)))
                    .hasMessageStartingWith("unknown option --type");
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

        @Test
        void oneAgentTakesConsoleLinesAsInstructionsAndPrintsWhatItSays() throws Exception {
            try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(20)
                    .start()) {
                int status = AgentMain.agent(List.of("--type", "guppy", "--name", "Gup", "--host", "127.0.0.1",
                        "--port", String.valueOf(server.port())), console("explore\n\ndance\n"), print(out), print(err));

                assertThat(status).isZero();
            }
            assertThat(out()).contains("Gup (guppy) is connecting to 127.0.0.1:", "Gup: Exploring.", "Gup: I didn't understand 'dance'",
                    "Game over (time limit reached). Ranking:", "1. Gup", "Gup: ");
        }

        @Test
        void allFiveTakeInstructionsAddressedByName() throws Exception {
            try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP).timeLimit(10)
                    .waitFor(5).start()) {
                int status = AgentMain.agents(List.of("--host", "127.0.0.1", "--port", String.valueOf(server.port())),
                        console("Dwarf: stop\nroadrunner carry on\nGuppy, turn left\nnobody: hello\n"), print(out), print(err));

                assertThat(status).isZero();
            }
            assertThat(out()).contains("Dwarf, Robot, Bunny, Guppy, Roadrunner are connecting to 127.0.0.1:", "Dwarf: Stopping.",
                    "Roadrunner: Carrying on by myself.", "Guppy: Turning left.", "Start the line with the agent's name",
                    "Game over", "Bunny: ");
        }
    }
}
