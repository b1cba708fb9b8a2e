package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A new agent as a student writes it: a subclass of AgentController of under 40 lines. */
class StudentAgentTest {

    @Test
    void aStudentsAgentOfUnderFortyLinesRegistersWandersAndCollects() throws Exception {
        Pippin pippin = new Pippin();

        Games.Result game = Games.play(1998, 120, List.of(pippin));

        assertThat(game.over().ranking()).extracting(s -> s.agent()).containsExactly("Pippin");
        assertThat(pippin.stats().movesSent()).isGreaterThan(10);
        assertThat(pippin.stats().fruit()).isGreaterThanOrEqualTo(1);
    }

    @Test
    void theStudentsAgentIsUnderFortyLines() throws Exception {
        List<String> lines = Files.readAllLines(Path.of("src/test/java/io/orchard/agents/Pippin.java"));
        int declaration = lines.indexOf("public final class Pippin extends AgentController {");

        assertThat(declaration).isPositive();
        assertThat(lines.size() - declaration).as("lines of the class, imports aside").isLessThan(40);
    }
}
