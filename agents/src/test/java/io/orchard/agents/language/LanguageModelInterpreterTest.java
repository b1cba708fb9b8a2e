package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.net.ServerSocket;
import java.net.URI;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import tools.jackson.databind.JsonNode;

/** The language model is asked only for what the grammar does not understand, and its answer is checked. */
class LanguageModelInterpreterTest {

    /** A sentence the grammar does not understand, which a model may. */
    static final String ODD = "I would be ever so grateful for one of those long yellow things";
    static final String NEAREST_BANANA = "{\"goal\":\"collect\",\"what\":{\"kind\":\"banana\",\"distance\":\"nearest\"},"
            + "\"count\":1}";

    private final InstructionInterpreter grammar = new InstructionInterpreter(List.of("Pupil"));
    private FakeLanguageModel model;
    private LanguageModelInterpreter interpreter;

    @BeforeEach
    void start() throws Exception {
        model = new FakeLanguageModel();
        interpreter = new LanguageModelInterpreter(grammar, model.model(Duration.ofSeconds(10)));
    }

    @AfterEach
    void stop() {
        model.close();
    }

    @Test
    void aSentenceTheGrammarUnderstandsIsReadByTheGrammarAloneAndTheModelIsNotAsked() {
        model.answers("{\"goal\":\"stop\"}");

        Interpretation heard = interpreter.interpret("pick up the nearest banana");

        assertThat(heard).isEqualTo(grammar.interpret("pick up the nearest banana"));
        assertThat(model.requests()).isEmpty();
    }

    @Test
    void aSentenceTheGrammarDoesNotUnderstandGoesToTheModelWhoseGoalIsRestatedBeforeActing() {
        assertThat(grammar.interpret(ODD)).isInstanceOf(Interpretation.NotUnderstood.class);
        model.answers("Sure! Here is the goal:\n```json\n" + NEAREST_BANANA + "\n```");

        Interpretation heard = interpreter.interpret(ODD);

        assertThat(heard).isInstanceOfSatisfying(Interpretation.Understood.class, understood -> {
            assertThat(understood.goal()).isEqualTo(GoalJson.read(NEAREST_BANANA));
            assertThat(understood.restatement()).isEqualTo("I asked a language model, which read that as: collect(nearest banana).");
        });
        JsonNode request = model.requests().get(0);
        assertThat(request.path("model").asString()).isEqualTo("fake-model");
        assertThat(request.path("temperature").asInt()).isZero();
        assertThat(request.path("messages").path(1).path("role").asString()).isEqualTo("user");
        assertThat(request.path("messages").path(1).path("content").asString()).isEqualTo(ODD);
        assertThat(request.path("messages").path(0).path("content").asString())
                .contains("\"$defs\"", "get the nearest banana on a table => {\"goal\":\"collect\"");
    }

    @Test
    void aGoalOutsideTheSchemaIsNotPursuedAndThePersonIsToldWhy() {
        model.answers("{\"goal\":\"go-to\",\"destination\":{\"kind\":\"castle\"},\"speed\":\"fast\"}");

        Interpretation heard = interpreter.interpret(ODD);

        String grammarsAnswer = ((Interpretation.NotUnderstood) grammar.interpret(ODD)).answer();
        assertThat(heard).isInstanceOfSatisfying(Interpretation.NotUnderstood.class, refused -> assertThat(
                refused.answer()).startsWith(grammarsAnswer + " (The language model could not help: its goal "
                        + "{\"goal\":\"go-to\"").contains("does not fit the goals' schema", "speed"));
    }

    @Test
    void aModelThatFindsNoGoalLeavesTheGrammarsAnswer() {
        model.answers("{\"goal\": null}");

        assertThat(interpreter.interpret(ODD)).isEqualTo(grammar.interpret(ODD));
        assertThat(model.requests()).hasSize(1);
    }

    @Test
    void anAnswerThatIsNoJsonObjectIsSaidToBeOne() {
        model.answers("I think they want a banana.");

        assertThat(((Interpretation.NotUnderstood) interpreter.interpret(ODD)).answer())
                .endsWith("(The language model could not help: it answered no JSON object: "
                        + "'I think they want a banana.'.)");
    }

    @Test
    void aServerErrorIsNamed() {
        model.status(500);

        assertThat(((Interpretation.NotUnderstood) interpreter.interpret(ODD)).answer())
                .contains("answered HTTP 500");
    }

    @Test
    void aModelTooSlowForItsTimeoutIsNotWaitedFor() {
        model.delay(Duration.ofSeconds(5));
        LanguageModelInterpreter impatient = new LanguageModelInterpreter(grammar, model.model(Duration.ofMillis(300)));

        long started = System.nanoTime();
        Interpretation heard = impatient.interpret(ODD);

        assertThat(Duration.ofNanos(System.nanoTime() - started)).isLessThan(Duration.ofSeconds(4));
        assertThat(((Interpretation.NotUnderstood) heard).answer()).contains("no answer from http://127.0.0.1:");
    }

    @Test
    void noServerAtTheAddressIsNamed() throws Exception {
        int port;
        try (ServerSocket free = new ServerSocket(0)) {
            port = free.getLocalPort();
        }
        LanguageModelInterpreter nowhere = new LanguageModelInterpreter(grammar,
                new LanguageModel(URI.create("http://127.0.0.1:" + port + "/v1"), "m", Duration.ofSeconds(2)));

        assertThat(((Interpretation.NotUnderstood) nowhere.interpret(ODD)).answer())
                .contains("no answer from http://127.0.0.1:" + port + "/v1/chat/completions");
    }

    @Test
    void badSettingsAreRefusedNamingTheValue() {
        assertThatThrownBy(() -> new LanguageModel(URI.create("ftp://host/v1"), "m", Duration.ofSeconds(1)))
                .hasMessageContaining("'ftp://host/v1'");
        assertThatThrownBy(() -> new LanguageModel(URI.create("http://host/v1"), " ", Duration.ofSeconds(1)))
                .hasMessageContaining("model must name");
        assertThatThrownBy(() -> new LanguageModel(URI.create("http://host/v1"), "m", Duration.ZERO))
                .hasMessageContaining("timeout must be more than 0, was PT0S");
        assertThat(new LanguageModel(URI.create("http://host:8080/v1/"), "m", Duration.ofSeconds(1)).completions())
                .isEqualTo(URI.create("http://host:8080/v1/chat/completions"));
    }
}
