package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.cli.UsageException;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

class ParseCommandTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) throws UsageException {
        return new ParseCommand().run(List.of(args), print(out), print(err));
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8).replace("\r\n", "\n");
    }

    private static PrintStream print(ByteArrayOutputStream bytes) {
        return new PrintStream(bytes, true, StandardCharsets.UTF_8);
    }

    @Test
    void printsTheGoalAsJsonAndTheRestatement() throws UsageException {
        assertThat(run("get the nearest banana on a table")).isZero();
        assertThat(out()).isEqualTo("""
                {
                  "goal" : "collect",
                  "what" : {
                    "kind" : "banana",
                    "distance" : "nearest",
                    "place" : {
                      "relation" : "on",
                      "anchor" : {
                        "kind" : "table"
                      }
                    }
                  },
                  "count" : 1
                }
                Going to pick up the nearest banana that lies on a table.
                """);
        assertThat(err.size()).isZero();
    }

    @Test
    void severalWordsAreOneSentence() throws UsageException {
        assertThat(run("--notation", "go", "to", "the", "castle", "and", "then", "pick", "up", "a", "tomato")).isZero();
        assertThat(out()).isEqualTo("go-to(castle); collect(tomato)\nGoing to the castle, then picking up a tomato.\n");
    }

    @Test
    void printsTheAddressee() throws UsageException {
        assertThat(run("--notation", "Guppy, stop")).isZero();
        assertThat(out()).isEqualTo("Addressed to Guppy.\nstop\nStopping.\n");
    }

    @Test
    void aSentenceNotUnderstoodGetsTheAnswerAndStatus0() throws UsageException {
        assertThat(run("jump over the moon")).isZero();
        assertThat(out()).isEqualTo("I didn't understand 'jump over the moon' (I don't know 'jump' or 'moon'); "
                + "I can go to places, collect fruit, explore, follow, turn, stop.\n");
    }

    @Test
    void knowsTheAgentsItIsTold() throws UsageException {
        assertThat(run("--agents", "Alice,Bob", "--notation", "follow alice")).isZero();
        assertThat(out()).startsWith("follow(Alice)\n");
    }

    @Test
    void everythingAfterTwoDashesIsTheSentence() throws UsageException {
        assertThat(run("--", "--notation")).isZero();
        assertThat(out()).startsWith("I didn't understand");
    }

    @Test
    void noSentenceIsAUsageError() {
        assertThatThrownBy(this::run).isInstanceOf(UsageException.class).hasMessageContaining("expected a sentence");
        assertThatThrownBy(() -> run("--agents")).isInstanceOf(UsageException.class).hasMessageContaining("--agents");
        assertThatThrownBy(() -> run("--loud", "stop")).isInstanceOf(UsageException.class)
                .hasMessageContaining("'--loud'");
    }

    @Test
    void theLauncherListsAndRunsIt() {
        int status = Orchard.run(new String[] {"parse", "--notation", "turn left"}, print(out), print(err));
        assertThat(status).isZero();
        assertThat(out()).isEqualTo("turn(90)\nTurning left.\n");
        assertThat(new ParseCommand().help()).startsWith("Usage: ./orchard parse");
        assertThat(Orchard.COMMANDS).extracting(Command::name).contains("parse");
    }
}
