package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Interpretation.NotUnderstood;
import io.orchard.agents.language.Interpretation.Understood;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The corpus of instructions in {@code language/corpus.tsv}: each sentence must be understood as
 * its expected goal (in {@link Goal#notation()}, with "@Name " for an addressee), or refused,
 * naming exactly the listed unknown words.
 */
class CorpusTest {

    private static final String CORPUS = "/language/corpus.tsv";
    private static final String REFUSE = "refuse";

    private static final InstructionInterpreter INTERPRETER = new InstructionInterpreter();

    /**
     * One line of the corpus.
     *
     * @param line     its line number, to find it
     * @param sentence the instruction
     * @param expected the expected notation, or "refuse" with optional unknown words
     */
    record Case(int line, String sentence, String expected) {

        boolean refused() {
            return expected.startsWith(REFUSE);
        }

        @Override
        public String toString() {
            return line + ": " + sentence;
        }
    }

    static List<Case> corpus() {
        List<Case> cases = new ArrayList<>();
        try (InputStream in = Objects.requireNonNull(CorpusTest.class.getResourceAsStream(CORPUS), CORPUS);
             BufferedReader reader = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            String text;
            int line = 0;
            while ((text = reader.readLine()) != null) {
                line++;
                if (text.isBlank() || text.startsWith("#")) {
                    continue;
                }
                String[] fields = text.split("\t", -1);
                if (fields.length != 2) {
                    throw new IllegalStateException(CORPUS + ":" + line + " must be SENTENCE<TAB>EXPECTED, was '"
                            + text + "'");
                }
                cases.add(new Case(line, fields[0], fields[1].strip()));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return cases;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("corpus")
    void sentenceIsUnderstoodAsExpected(Case c) {
        Interpretation interpretation = INTERPRETER.interpret(c.sentence());
        if (c.refused()) {
            assertThat(interpretation).as(c.sentence()).isInstanceOf(NotUnderstood.class);
            NotUnderstood refusal = (NotUnderstood) interpretation;
            assertThat(refusal.answer()).isNotBlank();
            String words = c.expected().substring(REFUSE.length()).strip();
            if (words.startsWith(":")) {
                List<String> unknown = Arrays.stream(words.substring(1).split(",")).map(String::strip).toList();
                assertThat(refusal.unknownWords()).as(c.sentence()).isEqualTo(unknown);
                unknown.forEach(word -> assertThat(refusal.answer()).contains("'" + word + "'"));
            }
        } else {
            assertThat(interpretation).as(c.sentence()).isInstanceOf(Understood.class);
            Understood understood = (Understood) interpretation;
            String notation = understood.addressee().map(name -> "@" + name + " ").orElse("")
                    + understood.goal().notation();
            assertThat(notation).as(c.sentence()).isEqualTo(c.expected());
            assertThat(understood.restatement()).matches("[A-Z][^\\n]*\\.");
            assertThat(GoalJson.write(understood.goal())).startsWith("{\"goal\":");
        }
    }

    @Test
    void corpusHasAtLeast150InstructionsOfWhichAtLeast30AreRefused() {
        List<Case> cases = corpus();
        assertThat(cases).hasSizeGreaterThanOrEqualTo(150);
        assertThat(cases.stream().filter(Case::refused).count()).isGreaterThanOrEqualTo(30);
        assertThat(cases.stream().map(Case::sentence)).doesNotHaveDuplicates();
    }
}
