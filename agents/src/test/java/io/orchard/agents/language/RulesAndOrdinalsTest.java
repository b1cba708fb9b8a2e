package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Interpretation.NotUnderstood;
import io.orchard.agents.language.Interpretation.Understood;
import java.util.List;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Rules that hold until lifted, conditions, ordinals and demonstratives, as the grammar reads them:
 * the goal each sentence becomes (in the notation), what the agent says back, and what it asks
 * instead when it cannot read a sentence as one of them.
 */
class RulesAndOrdinalsTest {

    private final InstructionInterpreter interpreter = new InstructionInterpreter();

    private String notation(String sentence) {
        Interpretation heard = interpreter.interpret(sentence);
        assertThat(heard).as(sentence).isInstanceOf(Understood.class);
        return ((Understood) heard).goal().notation();
    }

    private String said(String sentence) {
        return ((Understood) interpreter.interpret(sentence)).restatement();
    }

    @Nested
    class Rules {

        @ParameterizedTest(name = "\"{0}\" is {1}")
        @CsvSource(delimiter = '|', value = {
            "don't go near the river | avoid(near(river))",
            "never go into the forest | avoid(forest)",
            "do not cross the river | avoid(beyond(river))",
            "stay on this side of the river | avoid(beyond(river))",
            "keep to this side of the river | avoid(beyond(river))",
            "stay away from the castle | avoid(near(castle))",
            "steer clear of Roadrunner | avoid(near(Roadrunner))",
            "stay out of the forest | avoid(forest)",
            "keep off the bridges | avoid(bridge)",
            "avoid the river | avoid(near(river))",
            "avoid going north of the castle | avoid(north-of(castle))",
            "don't go north | avoid(north-of(here))",
            "leave the coconuts alone | leave(coconut)",
            "ignore the tomatoes on the tables | leave(tomato on(table))",
            "no more coconuts | leave(coconut)",
            "never eat bananas again | leave(banana)",
            "avoid the coconuts | leave(coconut)",
            "only bananas from now on | only(banana)",
            "collect only bananas | only(banana)",
            "pick up coconuts only | only(coconut)",
            "from now on, nothing but tomatoes | only(tomato)",
            "you can go near the river again | lift(near(river))",
            "you may cross the river again | lift(beyond(river))",
            "feel free to eat tomatoes again | lift(tomato)",
            "forget the rules | lift",
            "forget all your rules | lift",
            "no more rules | lift",
            "cancel the rules | lift",
            "leave the coconuts and stay away from the river | leave(coconut); avoid(near(river))",
            "leave the coconuts and collect everything | leave(coconut); collect(all fruit)"
        })
        void aRuleIsAGoalThatHoldsUntilLifted(String sentence, String expected) {
            assertThat(notation(sentence)).isEqualTo(expected);
        }

        @ParameterizedTest(name = "\"{0}\" is said back as \"{1}\"")
        @CsvSource(delimiter = '|', value = {
            "don't go near the river | From now on I won't go near the river.",
            "stay on this side of the river | From now on I'll stay on this side of the river.",
            "never go into the forest | From now on I won't go into the forest.",
            "leave the coconuts | From now on I'll leave the coconuts alone.",
            "only bananas from now on | From now on I'll collect only bananas.",
            "you can go near the river again | All right: I may go near the river again.",
            "you may take coconuts again | All right: I may take coconuts again.",
            "forget the rules | All right: I've forgotten all my rules.",
            "when you see a banana, take it | From now on, whenever I see a banana, I'll pick it up.",
            "if you find a coconut, bring it to me | From now on, whenever I see a coconut, I'll pick it up, then come "
                    + "back.",
            "when you see Roadrunner, follow him | From now on, whenever I see Roadrunner, I'll follow him.",
            "if you see the castle, go there | From now on, whenever I see the castle, I'll go there."
        })
        void aRuleIsSaidBackAsItWillHold(String sentence, String restatement) {
            assertThat(said(sentence)).isEqualTo(restatement);
        }

        @Test
        void aRuleStatesItselfAndGivesItselfAsAReason() {
            Rule avoid = (Rule) ((Understood) interpreter.interpret("don't go near the river")).goal();
            Rule bank = (Rule) ((Understood) interpreter.interpret("stay on this side of the river")).goal();
            Rule leave = (Rule) ((Understood) interpreter.interpret("leave the coconuts")).goal();
            Rule when = (Rule) ((Understood) interpreter.interpret("whenever you see a tomato, grab it")).goal();

            assertThat(avoid.statement()).isEqualTo("I don't go near the river");
            assertThat(avoid.reason()).isEqualTo("your rule not to go near the river");
            assertThat(bank.statement()).isEqualTo("I stay on this side of the river");
            assertThat(bank.reason()).isEqualTo("your rule to stay on this side of the river");
            assertThat(leave.reason()).isEqualTo("your rule to leave the coconuts alone");
            assertThat(when.statement()).isEqualTo("whenever I see a tomato, I pick it up");
        }

        @ParameterizedTest(name = "\"{0}\"")
        @CsvSource(delimiter = '|', value = {
            "don't look at the castle | rather than what not to do",
            "only go north | Which fruit should I take from now on?",
            "leave the castle | What should I leave alone?",
            "always explore | I can keep from now on only rules",
            "when you see a banana | What should I do when I see a banana?",
            "when you see a banana, forget the rules | only when I see something",
            "if you are hungry, eat a banana | I can act when I see something"
        })
        void whatNoRuleCanSayIsRefusedWithWhatCan(String sentence, String answer) {
            Interpretation heard = interpreter.interpret(sentence);
            assertThat(heard).as(sentence).isInstanceOf(NotUnderstood.class);
            assertThat(((NotUnderstood) heard).answer()).contains(answer);
        }

        @Test
        void withoutAgainYouCanIsAPoliteCommandNotALift() {
            assertThat(notation("you can go to the castle")).isEqualTo("go-to(castle)");
            assertThat(notation("go to the castle again")).isEqualTo("go-to(castle)");
        }
    }

    @Nested
    class Conditions {

        @ParameterizedTest(name = "\"{0}\" is {1}")
        @CsvSource(delimiter = '|', value = {
            "when you see a banana, take it | when-see(banana): collect(banana)",
            "when you see a banana take it | when-see(banana): collect(banana)",
            "as soon as you spot a coconut on a table, pick it up | when-see(coconut on(table)): collect(coconut on(table))",
            "each time you see a tomato, eat it and come back | when-see(tomato): collect(tomato); come-back",
            "pick up the bananas when you see them | when-see(banana): collect(all banana)",
            "if there is a banana, grab it | when-see(banana): collect(banana)",
            "whenever you see Guppy, stop | when-see(Guppy): stop",
            "if you could, go north | head(north)"
        })
        void aConditionIsWhatToDoEachTimeSomethingIsSeen(String sentence, String expected) {
            assertThat(notation(sentence)).isEqualTo(expected);
        }

        @Test
        void whatAConditionDoesIsReadBackFromJson() {
            Goal goal = ((Understood) interpreter.interpret("if you find a banana, bring it to me")).goal();

            assertThat(GoalJson.write(goal)).isEqualTo("{\"goal\":\"when-see\",\"what\":{\"kind\":\"banana\"},"
                    + "\"then\":{\"goal\":\"sequence\",\"steps\":[{\"goal\":\"collect\",\"what\":{\"kind\":\"banana\"},"
                    + "\"count\":1},{\"goal\":\"come-back\"}]}}");
            assertThat(GoalJson.read(GoalJson.write(goal))).isEqualTo(goal);
        }
    }

    @Nested
    class Ordinals {

        @ParameterizedTest(name = "\"{0}\" is {1}")
        @CsvSource(delimiter = '|', value = {
            "go to the second table from the left | go-to(2nd leftmost table)",
            "go to the third tree from the right | go-to(3rd rightmost tree)",
            "go to the leftmost tree | go-to(leftmost tree)",
            "go to the first table from the left | go-to(leftmost table)",
            "take the third banana | collect(3rd nearest banana)",
            "walk to the 2nd tree | go-to(2nd nearest tree)",
            "pick up the second highest coconut | collect(2nd highest coconut)",
            "go to the fourth farthest tree | go-to(4th farthest tree)",
            "wait a second | wait(1)",
            "collect two bananas | collect(2 banana)"
        })
        void anOrdinalCountsInTheOrderOfASuperlative(String sentence, String expected) {
            assertThat(notation(sentence)).isEqualTo(expected);
        }

        @Test
        void anOrdinalIsSaidBackInWords() {
            assertThat(said("go to the second table from the left")).isEqualTo(
                    "Going to the second table from the left.");
            assertThat(said("take the third banana")).isEqualTo("Going to pick up the third nearest banana.");
        }
    }

    @Nested
    class Demonstratives {

        private final Discourse spokeOfATable = new Discourse(List.of(
                new Discourse.Mention(Reference.Kind.BANANA, "F12"), new Discourse.Mention(Reference.Kind.TABLE, "D3"),
                new Discourse.Mention(Reference.Kind.AGENT, "Guppy")));

        private String notation(String sentence, Discourse discourse) {
            Interpretation heard = interpreter.interpret(sentence, discourse);
            assertThat(heard).as(sentence).isInstanceOf(Understood.class);
            return ((Understood) heard).goal().notation();
        }

        @Test
        void thatTableIsTheLastTableTheAgentSpokeOf() {
            assertThat(notation("collect all the tomatoes on that table", spokeOfATable))
                    .isEqualTo("collect(all tomato on(table#D3))");
            assertThat(notation("go to that table", spokeOfATable)).isEqualTo("go-to(table#D3)");
            assertThat(said("go to the table and collect everything on that table"))
                    .isEqualTo("Going to a table, then picking up all the fruit that lie on a table.");
        }

        @Test
        void itIsTheLastThingSpokenOfWhenTheSentenceNamedNone() {
            assertThat(notation("pick it up", spokeOfATable)).isEqualTo("collect(banana#F12)");
            assertThat(notation("follow him", spokeOfATable)).isEqualTo("follow(Guppy)");
            assertThat(((Understood) interpreter.interpret("go to that table", spokeOfATable)).restatement())
                    .isEqualTo("Going to the table D3.");
        }

        @Test
        void withNothingSpokenOfTheAgentAsksWhichOneIsMeant() {
            Interpretation heard = interpreter.interpret("go to that tree", spokeOfATable);

            assertThat(heard).isInstanceOf(NotUnderstood.class);
            assertThat(((NotUnderstood) heard).answer()).startsWith("I don't know which one you mean by 'that tree'");
            assertThat(interpreter.interpret("pick it up")).isInstanceOf(NotUnderstood.class);
        }
    }
}
