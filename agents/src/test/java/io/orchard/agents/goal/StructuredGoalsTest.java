package io.orchard.agents.goal;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class StructuredGoalsTest {

    @ParameterizedTest(name = "\"{0}\"")
    @ValueSource(strings = {"go to 10,-20", "Go to 10, -20.", "goto 10 -20", "go to (10, -20)", "walk to 10,-20!"})
    void goToReadsTwoNumbers(String text) throws NotUnderstoodException {
        assertThat(StructuredGoals.parse(text)).isEqualTo(new Goal.GoTo(new Point2(10, -20)));
    }

    @ParameterizedTest(name = "\"{0}\"")
    @ValueSource(strings = {"collect banana", "Collect bananas", "collect a banana", "get the banana", "pick up banana"})
    void collectReadsAKind(String text) throws NotUnderstoodException {
        assertThat(StructuredGoals.parse(text)).isEqualTo(new Goal.Collect(FruitKind.BANANA, null));
    }

    @Test
    void collectReadsAFruitIdOrNothing() throws NotUnderstoodException {
        assertThat(StructuredGoals.parse("collect F12")).isEqualTo(new Goal.Collect(null, "F12"));
        assertThat(StructuredGoals.parse("collect tomatoes")).isEqualTo(new Goal.Collect(FruitKind.TOMATO, null));
        assertThat(StructuredGoals.parse("collect")).isEqualTo(Goal.Collect.any());
        assertThat(StructuredGoals.parse("collect fruit")).isEqualTo(Goal.Collect.any());
    }

    @Test
    void theWordsWithoutArguments() throws NotUnderstoodException {
        assertThat(StructuredGoals.parse("Stop!")).isEqualTo(new Goal.Stop());
        assertThat(StructuredGoals.parse("wait")).isEqualTo(new Goal.Stop());
        assertThat(StructuredGoals.parse("carry on")).isEqualTo(new Goal.CarryOn());
        assertThat(StructuredGoals.parse("continue")).isEqualTo(new Goal.CarryOn());
        assertThat(StructuredGoals.parse("explore")).isEqualTo(new Goal.Explore());
    }

    @Test
    void whatIsNotUnderstoodIsNamedWithWhatWouldBe() {
        assertThatThrownBy(() -> StructuredGoals.parse("dance"))
                .isInstanceOf(NotUnderstoodException.class)
                .hasMessage("'dance' is not an instruction I know; " + StructuredGoals.USAGE);
        assertThatThrownBy(() -> StructuredGoals.parse("go to the castle"))
                .hasMessage("'go to the castle': expected two numbers after 'go to', as in 'go to 10,-20'");
        assertThatThrownBy(() -> StructuredGoals.parse("collect pears"))
                .hasMessageContaining("expected a kind of fruit (tomato, banana, coconut) or a fruit's id (F12)");
    }

    @Test
    void goalsDescribeThemselves() {
        assertThat(new Goal.GoTo(new Point2(10, -20)).describe()).isEqualTo("go to (10.0, -20.0)");
        assertThat(new Goal.Collect(FruitKind.COCONUT, null).describe()).isEqualTo("collect a coconut");
        assertThat(new Goal.Collect(null, "F3").describe()).isEqualTo("collect F3");
    }
}
