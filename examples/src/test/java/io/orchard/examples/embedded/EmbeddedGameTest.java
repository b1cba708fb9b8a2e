package io.orchard.examples.embedded;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Score;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The embedding example plays a real game on a free port and prints its events and the ranking. */
class EmbeddedGameTest {

    @Test
    void theEmbeddedGamePrintsItsEventsAndTheRankingOfBothAgents() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);

        List<Score> ranking = EmbeddedGame.play(1998, 20, out);

        String printed = bytes.toString(StandardCharsets.UTF_8);
        assertThat(ranking).extracting(Score::agent).containsExactlyInAnyOrder("Dwarf", "Robot");
        assertThat(printed).containsPattern("world server on port \\d+, seed 1998")
                .contains("game started: seed 1998", "game over: ", "Ranking:")
                .containsPattern("  1\\. (Dwarf|Robot) +\\d+ points +\\d+ fruit")
                .containsPattern("  2\\. (Dwarf|Robot) +\\d+ points +\\d+ fruit");
        int collected = ranking.stream().mapToInt(Score::fruit).sum();
        assertThat(printed.split(" collected ", -1)).as("one event line per fruit collected").hasSize(collected + 1);
    }
}
