package io.orchard.examples.tournament;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The bar on a fake clock, with the timings of a real five-game run whose first game started slowly. */
class ProgressBarTest {

    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private long now;

    private ProgressBar bar(boolean terminal) {
        return new ProgressBar(new PrintStream(bytes, true, StandardCharsets.UTF_8), terminal, 5, () -> now);
    }

    private void at(double seconds) {
        now = (long) (seconds * TimeUnit.SECONDS.toNanos(1));
    }

    /** What was drawn since the last call. */
    private String drawn() {
        String text = bytes.toString(StandardCharsets.UTF_8);
        bytes.reset();
        return text;
    }

    @Test
    void noTimeIsEstimatedBeforeTheFirstGameEndsHoweverSlowlyItStarts() {
        ProgressBar bar = bar(true);

        at(18); // starting up took 18 s, and the game's clock has barely moved
        bar.during(1, 0.0002, "game 1/5 (seed 1) t=0 s");

        assertThat(drawn()).isEqualTo("\r[..............................]   0% (18 s)  game 1/5 (seed 1) t=0 s\u001b[K");
    }

    @Test
    void theTimeLeftFollowsTheGamesFinishedTheLaterOnesOnceThereAreSome() {
        ProgressBar bar = bar(true);
        at(18);
        bar.during(1, 0.0002, "game 1/5 (seed 1) t=0 s");
        drawn();

        at(61);
        bar.finished(1, "game 1/5 (seed 1): 13 fruit");
        assertThat(drawn()).contains("20% (61 s, about 244 s left)");

        at(79);
        bar.finished(2, "game 2/5 (seed 2): 11 fruit");
        assertThat(drawn()).contains("40% (79 s, about 54 s left)");

        at(86);
        bar.during(3, 0.5, "game 3/5 (seed 3) t=150 s");
        assertThat(drawn()).contains("50% (86 s, about 47 s left)");

        at(93);
        bar.finished(3, "game 3/5 (seed 3): 14 fruit");
        at(107);
        bar.finished(4, "game 4/5 (seed 4): 15 fruit");
        at(120);
        bar.finished(5, "game 5/5 (seed 5): 14 fruit");
        assertThat(drawn()).contains("60% (93 s, about 32 s left)", "80% (107 s, about 15 s left)")
                .contains("100% (120 s)  game 5/5").doesNotContain("100% (120 s, about");
    }

    @Test
    void elsewhereThanATerminalOnlyFinishedGamesArePrintedEachOnALine() {
        ProgressBar bar = bar(false);
        at(18);
        bar.during(1, 0.0002, "game 1/5 (seed 1) t=0 s");
        at(61);
        bar.finished(1, "game 1/5 (seed 1): 13 fruit");

        assertThat(drawn()).isEqualTo("[######........................]  20% (61 s, about 244 s left)  game 1/5 (seed 1):"
                + " 13 fruit\n");
    }
}
