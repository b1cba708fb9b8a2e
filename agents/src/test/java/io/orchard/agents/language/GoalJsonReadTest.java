package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.agents.language.Interpretation.Understood;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Goals read back from their JSON: every goal of both sets of instructions, and bad JSON refused by name. */
class GoalJsonReadTest {

    private static final InstructionInterpreter INTERPRETER = new InstructionInterpreter();

    @Test
    void everyGoalOfBothSetsOfInstructionsIsReadBackAsItWasWritten() {
        List<String> sentences = new ArrayList<>();
        CorpusTest.corpus().forEach(c -> sentences.add(c.sentence()));
        FreshInstructionsTest.set().forEach(c -> sentences.add(c.sentence()));
        int goals = 0;
        for (String sentence : sentences) {
            if (INTERPRETER.interpret(sentence) instanceof Understood understood) {
                String json = GoalJson.write(understood.goal());
                assertThat(GoalJson.read(json)).as(json).isEqualTo(understood.goal());
                assertThat(GoalJson.read(GoalJson.writePretty(understood.goal()))).isEqualTo(understood.goal());
                goals++;
            }
        }
        assertThat(goals).isGreaterThan(400);
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "not json | not JSON",
        "[1] | goal must be a JSON object",
        "{\"goal\":\"jump\"} | goal.goal must be one of sequence, go-to",
        "{\"goal\":\"go-to\"} | goal.destination must be a reference",
        "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"moon\"}} | goal.destination.kind must be one of fruit",
        "{\"goal\":\"collect\",\"what\":{\"kind\":\"banana\"},\"count\":\"many\"} | goal.count must be a whole number",
        "{\"goal\":\"head\",\"direction\":\"up\"} | goal.direction must be a compass direction",
        "{\"goal\":\"ask\",\"topic\":\"meaning\"} | goal.topic must be one of see, where",
        "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"place\",\"place\":{\"relation\":\"inside\"}}}"
                + " | goal.destination.place.relation must be one of on, in",
        "{\"goal\":\"leave\",\"what\":{\"kind\":\"tree\"}} | only fruit can be left alone",
        "{\"goal\":\"when-see\",\"what\":{\"kind\":\"banana\"},\"then\":{\"goal\":\"lift\"}}"
                + " | must be an action, not lift",
        "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"tree\",\"ordinal\":2}} | the distance is missing",
        "{\"goal\":\"go-to\",\"destination\":{\"kind\":\"castle\",\"id\":\"C1\"}} | an id names one fruit"
    })
    void badJsonIsRefusedNamingTheValueAndWhatWasExpected(String line) {
        String[] parts = line.split(" \\| ");
        assertThatThrownBy(() -> GoalJson.read(parts[0])).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining(parts[1]);
    }
}
