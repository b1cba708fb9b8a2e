package io.orchard.agents.errand;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.GoTo;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.Views;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Sight;
import java.util.Optional;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/** Asking which tree is meant, and reading the answers. */
class QuestionTest {

    private final WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), 0.4,
            new Sight(60, 2 * Math.PI));
    private final Grounder grounder = new Grounder(memory);
    private final Question question;

    QuestionTest() {
        // facing north from (0, 0): T1 straight ahead 20 away, T2 15 away to the right (east)
        Views.from(0, 0, 0).tree("T1", 0, -20, 2).tree("T2", 15, 0, 2).into(memory);
        Reference tree = Reference.to(Reference.Kind.TREE);
        Grounding grounding = grounder.ground(tree);
        assertThat(grounding).isInstanceOf(Grounding.Ambiguous.class);
        question = new Question(new GoTo(tree), Reference.Kind.TREE, ((Grounding.Ambiguous) grounding).choices(),
                memory, grounder, new Speech(Language.ENGLISH));
    }

    @Test
    void theQuestionListsTheChoicesInWordsThatCanBeAnsweredWith() {
        assertThat(question.text()).isEqualTo("Which tree do you mean? "
                + "1: the nearer one, 15 m to the east, the right one (T2); "
                + "2: the farther one, 20 m to the north, the left one (T1). "
                + "Say 'the nearer one', a direction or a number.");
    }

    @Test
    void inGermanTheQuestionIsAskedAndAnsweredInGerman() {
        Reference tree = Reference.to(Reference.Kind.TREE);
        Question german = new Question(new GoTo(tree), Reference.Kind.TREE,
                ((Grounding.Ambiguous) grounder.ground(tree)).choices(), memory, grounder, new Speech(Language.GERMAN));

        assertThat(german.text()).isEqualTo("Welchen Baum meinst du? "
                + "1: den näheren, 15 m Richtung Osten, den rechten (T2); "
                + "2: den weiteren, 20 m Richtung Norden, den linken (T1). "
                + "Sag 'den näheren', eine Richtung oder eine Zahl.");
        assertThat(german.read("den näheren")).map(Known::id).contains("T2");
        assertThat(german.read("den linken")).map(Known::id).contains("T1");
        assertThat(german.read("den im Norden")).map(Known::id).contains("T1");
        assertThat(german.read("den zweiten")).map(Known::id).contains("T1");
    }

    @ParameterizedTest(name = "\"{0}\" means {1}")
    @CsvSource({
        "the nearer one, T2", "the closest, T2", "1, T2", "the first one, T2", "east, T2", "the right one, T2",
        "t2, T2", "the farther one, T1", "2, T1", "the second, T1", "the north one, T1", "the left one, T1",
        "the other one, T1", "number 2 please, T1"})
    void anAnswerPicksOutOneChoice(String answer, String meant) {
        assertThat(question.read(answer)).map(Known::id).contains(meant);
    }

    @Test
    void amongMoreThanTwoTheChoicesAreCountedFromTheNearest() {
        Views.from(0, 0, 0).tree("T3", -40, 0, 2).into(memory);
        Reference tree = Reference.to(Reference.Kind.TREE);
        Question three = new Question(new GoTo(tree), Reference.Kind.TREE,
                ((Grounding.Ambiguous) grounder.ground(tree)).choices(), memory, grounder, new Speech(Language.ENGLISH));

        assertThat(three.text()).startsWith("Which tree do you mean? 1: the nearest one, 15 m to the east (T2); "
                + "2: the second nearest, 20 m to the north (T1); 3: the third nearest, 40 m to the west (T3).");
        assertThat(three.read("the second nearest")).map(Known::id).contains("T1");
        assertThat(three.read("the nearest one")).map(Known::id).contains("T2");
        assertThat(three.read("the farthest")).map(Known::id).contains("T3");
        assertThat(three.read("the west one")).map(Known::id).contains("T3");
    }

    @ParameterizedTest(name = "\"{0}\"")
    @ValueSource(strings = {"banana", "go north-west", "the nearer one on the left", "3", ""})
    void whatPicksOutNoneOrBothIsNoAnswer(String answer) {
        assertThat(question.read(answer)).isEqualTo(Optional.empty());
    }
}
