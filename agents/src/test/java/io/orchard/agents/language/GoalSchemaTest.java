package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.networknt.schema.InputFormat;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The goals' JSON Schema takes every goal the grammar makes and refuses what GoalJson.read refuses. */
class GoalSchemaTest {

    private static final Path PUBLISHED = Path.of("..", "docs", "goal.schema.json");
    private static Schema schema;

    @BeforeAll
    static void load() {
        schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12)
                .getSchema(GoalSchema.json(), InputFormat.JSON);
    }

    @Test
    void thePublishedSchemaIsTheOneTheCodeMakes() throws IOException {
        if ("write".equals(System.getProperty("orchard.goal.schema"))) {
            Files.writeString(PUBLISHED, GoalSchema.json(), StandardCharsets.UTF_8);
        }
        assertThat(Files.readString(PUBLISHED, StandardCharsets.UTF_8))
                .as("docs/goal.schema.json; write it again with ./mvnw -pl agents test -Dtest=GoalSchemaTest "
                        + "-Dorchard.goal.schema=write")
                .isEqualTo(GoalSchema.json());
    }

    @Test
    void everyGoalTheGrammarMakesOfBothSetsOfInstructionsFitsTheSchema() throws IOException {
        InstructionInterpreter grammar = new InstructionInterpreter();
        int goals = 0;
        for (String sentence : InstructionSets.sentences()) {
            if (grammar.interpret(sentence) instanceof Interpretation.Understood understood) {
                String json = GoalJson.write(understood.goal());
                assertThat(schema.validate(json, InputFormat.JSON)).as("\"%s\" as %s", sentence, json).isEmpty();
                assertThat(GoalJson.read(json)).isEqualTo(understood.goal());
                goals++;
            }
        }
        InstructionInterpreter german = new InstructionInterpreter(java.util.List.of(), Language.GERMAN);
        for (String sentence : InstructionSets.german()) {
            if (german.interpret(sentence) instanceof Interpretation.Understood understood) {
                String json = GoalJson.write(understood.goal());
                assertThat(schema.validate(json, InputFormat.JSON)).as("\"%s\" as %s", sentence, json).isEmpty();
                goals++;
            }
        }
        assertThat(goals).as("goals checked").isGreaterThan(400);
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "{\"goal\":\"dance\"}",
        "{\"goal\":\"collect\",\"what\":{\"kind\":\"tree\"},\"count\":1}",
        "{\"goal\":\"collect\",\"what\":{\"kind\":\"banana\"},\"count\":0}",
        "{\"goal\":\"collect\",\"what\":{\"kind\":\"banana\"}}",
        "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"castle\",\"place\":{\"relation\":\"inside-of\"}}}",
        "{\"goal\":\"sequence\",\"steps\":[{\"goal\":\"stop\"}]}",
        "{\"goal\":\"sequence\",\"steps\":[{\"goal\":\"stop\"},{\"goal\":\"sequence\",\"steps\":"
                + "[{\"goal\":\"stop\"},{\"goal\":\"carry-on\"}]}]}",
        "{\"goal\":\"head\",\"direction\":\"up\"}",
        "{\"goal\":\"move\",\"direction\":\"forward\",\"distance\":0}",
        "{\"goal\":\"ask\",\"topic\":\"the-weather\"}",
        "{\"goal\":\"wait\",\"seconds\":-1}",
        "{\"goal\":\"leave\",\"what\":{\"kind\":\"tree\"}}",
        "{\"goal\":\"when-see\",\"what\":{\"kind\":\"banana\"},\"then\":{\"goal\":\"lift\"}}",
        "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"tree\",\"ordinal\":2}}"})
    void whatGoalJsonRefusesTheSchemaRefusesToo(String json) {
        assertThatThrownBy(() -> GoalJson.read(json)).isInstanceOf(IllegalArgumentException.class);
        assertThat(schema.validate(json, InputFormat.JSON)).as(json).isNotEmpty();
    }

    @Test
    void aFieldNoGoalHasIsRefusedSoThatAModelCannotSlipInAPartNoOneActsOn() {
        String json = "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"castle\"},\"speed\":\"fast\"}";

        assertThat(schema.validate(json, InputFormat.JSON)).as(json).isNotEmpty();
        assertThat(schema.validate("{\"goal\":\"go-to\",\"destination\":{\"kind\":\"castle\"}}", InputFormat.JSON))
                .isEmpty();
    }
}
