package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import com.sun.net.httpserver.HttpServer;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class ParseCommandTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    /** Runs {@code ./orchard parse args}. */
    private int run(String... args) {
        return Orchard.run(Stream.concat(Stream.of("parse"), Stream.of(args)).toArray(String[]::new), print(out),
                print(err));
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8).replace("\r\n", "\n");
    }

    private static PrintStream print(ByteArrayOutputStream bytes) {
        return new PrintStream(bytes, true, StandardCharsets.UTF_8);
    }

    @Test
    void withLanguageDeAGermanSentenceIsReadAndRestatedInGerman() {
        assertThat(run("--language", "de", "--notation", "nimm die nächste Banane auf dem Tisch")).isZero();
        assertThat(out()).isEqualTo("""
                collect(nearest banana on(table))
                Read as German.
                Ich hebe die nächste Banane auf, die auf einem Tisch liegt.
                """);
        assertThat(run("--language", "fr", "go")).isEqualTo(2);
        assertThat(err()).contains("invalid value for option '--language': 'fr' (expected en or de)");
    }

    @Test
    void printsTheGoalAsJsonAndTheRestatement() {
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
    void aSentenceTheGrammarDoesNotKnowIsReadByTheLanguageModelWhenOneIsNamed() throws Exception {
        HttpServer model = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        byte[] answer = ("{\"choices\":[{\"message\":{\"role\":\"assistant\",\"content\":"
                + "\"{\\\"goal\\\":\\\"go-to\\\",\\\"destination\\\":{\\\"kind\\\":\\\"castle\\\"}}\"}}]}")
                .getBytes(StandardCharsets.UTF_8);
        model.createContext("/v1/chat/completions", exchange -> {
            exchange.getRequestBody().readAllBytes();
            exchange.sendResponseHeaders(200, answer.length);
            exchange.getResponseBody().write(answer);
            exchange.close();
        });
        model.start();
        try {
            assertThat(run("--notation", "--language-model", "http://127.0.0.1:" + model.getAddress().getPort() + "/v1",
                    "--language-model-name", "any", "wander over to the big stone house")).isZero();
        } finally {
            model.stop(0);
        }
        assertThat(out()).isEqualTo("go-to(castle)\nI asked a language model, which read that as: go-to(castle).\n");
    }

    @Test
    void aLanguageModelWithoutItsNameIsAUsageError() {
        assertThat(run("--language-model", "http://127.0.0.1:9/v1", "go home")).isEqualTo(2);
        assertThat(err()).contains("orchard parse: --language-model needs --language-model-name MODEL");
    }

    @Test
    void aQuestionSaysWhichQuestionItIs() {
        assertThat(run("--notation", "how many fruits have you got?")).isZero();
        assertThat(out()).isEqualTo("ask(collected)\nA question (collected): the agent answers it from what it knows "
                + "and goes on with what it was doing.\nYou asked what fruit I have collected.\n");
    }

    @Test
    void severalWordsAreOneSentence() {
        assertThat(run("--notation", "go", "to", "the", "castle", "and", "then", "pick", "up", "a", "tomato")).isZero();
        assertThat(out()).isEqualTo("go-to(castle); collect(tomato)\nGoing to the castle, then picking up a tomato.\n");
    }

    @Test
    void printsTheAddressee() {
        assertThat(run("--notation", "Guppy, stop")).isZero();
        assertThat(out()).isEqualTo("Addressed to Guppy.\nstop\nStopping.\n");
    }

    @Test
    void aSentenceNotUnderstoodGetsTheAnswerAndStatus0() {
        assertThat(run("jump over the moon")).isZero();
        assertThat(out()).isEqualTo("I didn't understand 'jump over the moon' (I don't know 'jump' or 'moon'); "
                + "I can go to places, collect fruit, explore, follow, turn, stop.\n");
    }

    @Test
    void knowsTheAgentsItIsTold() {
        assertThat(run("--agents", "Alice,Bob", "--notation", "follow alice")).isZero();
        assertThat(out()).startsWith("follow(Alice)\n");
    }

    @Test
    void everythingAfterTwoDashesIsTheSentence() {
        assertThat(run("--", "--notation")).isZero();
        assertThat(out()).startsWith("I didn't understand");
    }

    @Test
    void noSentenceIsAUsageError() {
        assertThat(run()).isEqualTo(2);
        assertThat(err()).contains("orchard parse: expected a sentence");
        err.reset();
        assertThat(run("--agents")).isEqualTo(2);
        assertThat(err()).contains("orchard parse: missing required parameter for option '--agents' (NAMES)");
        err.reset();
        assertThat(run("--agents", ",", "stop")).isEqualTo(2);
        assertThat(err()).contains("orchard parse: invalid value for option '--agents': ',' names no agent");
        err.reset();
        assertThat(run("--loud", "stop")).isEqualTo(2);
        assertThat(err()).contains("orchard parse: unknown option: '--loud'");
        assertThat(out()).isEmpty();
    }

    @Test
    void theLauncherListsAndRunsIt() {
        int status = Orchard.run(new String[] {"parse", "--notation", "turn left"}, print(out), print(err));
        assertThat(status).isZero();
        assertThat(out()).isEqualTo("turn(90)\nTurning left.\n");
        out.reset();
        assertThat(Orchard.run(new String[] {"help", "parse"}, print(out), print(err))).isZero();
        assertThat(out()).startsWith("Usage: orchard parse [OPTIONS] [SENTENCE...]");
        out.reset();
        assertThat(Orchard.run(new String[] {"--help"}, print(out), print(err))).isZero();
        assertThat(out()).containsPattern("\n  parse +Show how an agent understands an instruction in English\n");
    }
}
