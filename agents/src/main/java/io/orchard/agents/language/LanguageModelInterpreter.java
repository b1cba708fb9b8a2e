package io.orchard.agents.language;

import com.networknt.schema.InputFormat;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;
import java.io.IOException;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * An {@link Interpreter} that asks a language model for the sentences its grammar does not
 * understand. The grammar reads every sentence first, so whatever it understands is understood
 * exactly as without the model, and tournaments stay reproducible; only a sentence it gives up on
 * goes to the model, which is asked for a goal's JSON. The answer is checked against the
 * {@link GoalSchema goals' JSON Schema} and read with {@link GoalJson#read}; the goal is then
 * said to the person before the agent acts ("I asked a language model, which read
 * that as: collect(nearest banana)."). An answer that is no
 * goal, a model that cannot be reached or is too slow leave the grammar's own answer, with the
 * reason added: the person is never left guessing and a wrong goal is never pursued unsaid.
 *
 * <p>The agent waits for the model's answer before it decides again (at most the
 * {@linkplain LanguageModel#timeout() timeout}); a model on the same machine answers in well under
 * a second.
 */
public final class LanguageModelInterpreter implements Interpreter {

    private static final Logger log = LoggerFactory.getLogger(LanguageModelInterpreter.class);
    private static final JsonMapper MAPPER = JsonMapper.builder().build();
    /** Sentences whose goals, as the grammar reads them, show the model the form to answer in. */
    private static final List<String> EXAMPLES = List.of("get the nearest banana on a table",
            "go to the castle", "collect all the tomatoes", "walk north for 20 metres",
            "first go to the bridge, then look for coconuts", "what do you see?");

    private final Interpreter grammar;
    private final LanguageModel model;
    private final HttpClient http;
    private final Schema schema;
    private final String instructions;

    /** Asks {@code model} whenever {@code grammar} does not understand a sentence. */
    public LanguageModelInterpreter(Interpreter grammar, LanguageModel model) {
        this.grammar = Objects.requireNonNull(grammar, "grammar");
        this.model = Objects.requireNonNull(model, "model");
        this.http = HttpClient.newBuilder().connectTimeout(model.timeout()).build();
        this.schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12)
                .getSchema(GoalSchema.json(), InputFormat.JSON);
        this.instructions = instructions();
    }

    /** The interpreter it asks first, whose answers it keeps when they understand. */
    public Interpreter grammar() {
        return grammar;
    }

    @Override
    public Interpretation interpret(String sentence) {
        return interpret(sentence, Discourse.NONE);
    }

    /** As {@link #interpret(String)}, the grammar reading the sentence in what the agent spoke of last. */
    @Override
    public Interpretation interpret(String sentence, Discourse discourse) {
        Interpretation heard = grammar.interpret(sentence, discourse);
        if (!(heard instanceof Interpretation.NotUnderstood notUnderstood) || sentence == null
                || sentence.isBlank()) {
            return heard;
        }
        Optional<String> addressee = notUnderstood.addressee();
        try {
            Goal goal = goalOf(ask(sentence));
            if (goal == null) {
                return notUnderstood;
            }
            return new Interpretation.Understood(goal, "I asked a language model, which read that as: "
                    + goal.notation() + ".", addressee);
        } catch (Refused e) {
            log.info("the language model at {} could not read \"{}\": {}", model.endpoint(), sentence, e.getMessage());
            return new Interpretation.NotUnderstood(notUnderstood.answer() + " (The language model could not help: "
                    + e.getMessage() + ".)", notUnderstood.unknownWords(), addressee);
        }
    }

    /** The model's answer to the sentence: the text of its first choice. */
    private String ask(String sentence) throws Refused {
        ObjectNode body = MAPPER.createObjectNode();
        body.put("model", model.model());
        body.put("temperature", 0);
        body.putObject("response_format").put("type", "json_object");
        ArrayNode messages = body.putArray("messages");
        messages.addObject().put("role", "system").put("content", instructions);
        messages.addObject().put("role", "user").put("content", sentence);
        HttpRequest request = HttpRequest.newBuilder(model.completions()).timeout(model.timeout())
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(MAPPER.writeValueAsString(body), StandardCharsets.UTF_8))
                .build();
        HttpResponse<String> response;
        try {
            response = http.send(request, HttpResponse.BodyHandlers.ofString(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new Refused("no answer from " + model.completions() + " (" + describe(e) + ")");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new Refused("interrupted while waiting for " + model.completions());
        }
        if (response.statusCode() != 200) {
            throw new Refused(model.completions() + " answered HTTP " + response.statusCode());
        }
        try {
            JsonNode content = MAPPER.readTree(response.body()).path("choices").path(0).path("message")
                    .path("content");
            if (!content.isString()) {
                throw new Refused("its answer has no choices[0].message.content");
            }
            return content.asString();
        } catch (JacksonException e) {
            throw new Refused("its answer is not JSON");
        }
    }

    /** The goal in the model's text; null when the model said the sentence asks for no goal. */
    private Goal goalOf(String text) throws Refused {
        int start = text.indexOf('{');
        int end = text.lastIndexOf('}');
        if (start < 0 || end < start) {
            throw new Refused("it answered no JSON object: '" + abbreviate(text) + "'");
        }
        String json = text.substring(start, end + 1);
        JsonNode node;
        try {
            node = MAPPER.readTree(json);
        } catch (JacksonException e) {
            throw new Refused("it answered no JSON object: '" + abbreviate(json) + "'");
        }
        if (node.isObject() && node.has("goal") && node.get("goal").isNull()) {
            return null;
        }
        List<com.networknt.schema.Error> errors = schema.validate(json, InputFormat.JSON);
        if (!errors.isEmpty()) {
            throw new Refused("its goal " + abbreviate(json) + " does not fit the goals' schema: "
                    + errors.get(0).getMessage());
        }
        try {
            return GoalJson.read(json);
        } catch (IllegalArgumentException e) {
            throw new Refused("its goal " + abbreviate(json) + " is not one: " + e.getMessage());
        }
    }

    private String instructions() {
        StringBuilder text = new StringBuilder();
        text.append("You read instructions that a person gives to an agent in a small 3D world, and write each as a ")
                .append("goal in JSON. The world has a forest of trees, a castle, a river crossed by two bridges, ")
                .append("tables, and fruit (tomatoes, bananas, coconuts) that the agents collect. Answer with one ")
                .append("JSON object and nothing else. It must be valid against this JSON Schema:\n")
                .append(MAPPER.writeValueAsString(GoalSchema.tree()))
                .append("\nIf the sentence asks for nothing these goals can express, answer {\"goal\":null}.")
                .append(" Examples:\n");
        for (String example : EXAMPLES) {
            if (grammar.interpret(example) instanceof Interpretation.Understood understood) {
                text.append(example).append(" => ").append(GoalJson.write(understood.goal())).append('\n');
            }
        }
        return text.toString();
    }

    private static String describe(IOException e) {
        String message = e.getMessage();
        return message == null || message.isBlank() ? e.getClass().getSimpleName() : message;
    }

    private static String abbreviate(String text) {
        String line = text.replace('\n', ' ').strip();
        return line.length() <= 120 ? line : line.substring(0, 117) + "...";
    }

    /** Why the model's answer gave no goal, in words for the person. */
    private static final class Refused extends Exception {
        private static final long serialVersionUID = 1L;

        Refused(String reason) {
            super(reason, null, false, false);
        }
    }
}
