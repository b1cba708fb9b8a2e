package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Interpretation.NotUnderstood;
import io.orchard.agents.language.Interpretation.Understood;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * The fresh set of instructions in {@code language/fresh.tsv}, written as a new user types them:
 * the share understood as expected is reported (and kept in {@code docs/instructions.md}), and no
 * sentence may be misread, that is understood as a goal other than the one expected, or understood
 * at all when it must be refused.
 */
class FreshInstructionsTest {

    private static final String SET = "/language/fresh.tsv";

    /** The share understood that docs/instructions.md reports; the set may not fall below it. */
    private static final double REPORTED_SHARE = 1.0;

    private static final InstructionInterpreter INTERPRETER = new InstructionInterpreter();

    /** One line of the set: its number, the sentence and what is expected of it. */
    record Case(int line, String sentence, String expected) {

        boolean refused() {
            return expected.equals("refuse") || expected.equals("language");
        }

        /** What the interpreter made of the sentence, written as the set writes it. */
        String heard() {
            Interpretation interpretation = INTERPRETER.interpret(sentence);
            if (interpretation instanceof Understood understood) {
                return understood.addressee().map(name -> "@" + name + " ").orElse("")
                        + understood.goal().notation();
            }
            NotUnderstood refusal = (NotUnderstood) interpretation;
            return expected.equals("language") && refusal.answer().contains("English") ? "language" : "refuse";
        }
    }

    static List<Case> set() {
        try {
            return InstructionSets.lines(SET).stream().map(line -> {
                if (line.german()) {
                    throw new IllegalStateException(SET + ":" + line.number() + " must be SENTENCE<TAB>EXPECTED, "
                            + "with no third field");
                }
                return new Case(line.number(), line.sentence(), line.expected());
            }).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void noSentenceIsMisreadAndTheShareUnderstoodIsAsReported() {
        List<Case> cases = set();
        List<String> misread = new ArrayList<>();
        List<String> missed = new ArrayList<>();
        int understood = 0;
        for (Case c : cases) {
            String heard = c.heard();
            if (heard.equals(c.expected())) {
                understood++;
            } else if (heard.equals("refuse")) {
                missed.add(c.line() + ": " + c.sentence() + " -> not understood, expected " + c.expected());
            } else {
                misread.add(c.line() + ": " + c.sentence() + " -> " + heard + ", expected " + c.expected());
            }
        }
        double share = (double) understood / cases.size();
        System.out.printf(Locale.ROOT, "fresh instructions: %d of %d understood as expected (%.1f %%), %d misread%n",
                understood, cases.size(), 100 * share, misread.size());
        missed.forEach(line -> System.out.println("  missed " + line));
        assertThat(misread).as("sentences understood as something other than expected").isEmpty();
        assertThat(share).as("share understood").isGreaterThanOrEqualTo(REPORTED_SHARE);
    }

    @Test
    void theSetHasAtLeast200InstructionsOfEveryKind() {
        List<Case> cases = set();
        assertThat(cases).hasSizeGreaterThanOrEqualTo(200);
        assertThat(cases.stream().map(Case::sentence)).doesNotHaveDuplicates();
        assertThat(cases.stream().filter(c -> c.expected().startsWith("ask(")).count()).isGreaterThanOrEqualTo(30);
        assertThat(cases.stream().filter(Case::refused).count()).isGreaterThanOrEqualTo(20);
    }
}
