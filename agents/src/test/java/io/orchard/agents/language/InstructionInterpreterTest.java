package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Interpretation.NotUnderstood;
import io.orchard.agents.language.Interpretation.Understood;
import io.orchard.agents.language.Place.Relation;
import io.orchard.agents.language.Reference.Distance;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.protocol.value.Sector;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class InstructionInterpreterTest {

    private final InstructionInterpreter interpreter = new InstructionInterpreter();

    private Understood understood(String sentence) {
        Interpretation interpretation = interpreter.interpret(sentence);
        assertThat(interpretation).as(sentence).isInstanceOf(Understood.class);
        return (Understood) interpretation;
    }

    private Goal goal(String sentence) {
        return understood(sentence).goal();
    }

    private NotUnderstood refused(String sentence) {
        Interpretation interpretation = interpreter.interpret(sentence);
        assertThat(interpretation).as(sentence).isInstanceOf(NotUnderstood.class);
        return (NotUnderstood) interpretation;
    }

    @Test
    void understandsTheExampleAsATypedGoal() {
        Goal goal = goal("get the nearest banana on a table");
        Reference banana = new Reference(Kind.BANANA, null, null, Distance.NEAREST,
                Place.of(Relation.ON, Reference.to(Kind.TABLE)));
        assertThat(goal).isEqualTo(Collect.one(banana));
    }

    @Nested
    class Numbers {

        @ParameterizedTest(name = "\"{0}\" collects {1}")
        @CsvSource({
            "collect three bananas, 3",
            "collect 3 bananas, 3",
            "collect a couple of bananas, 2",
            "collect a few bananas, 3",
            "collect several bananas, 3",
            "collect some bananas, 3",
            "collect both bananas, 2",
            "collect a dozen bananas, 12",
            "collect twenty bananas, 20",
            "collect one banana, 1",
            "collect a banana, 1",
            "collect the banana, 1",
            "collect two of the bananas, 2"
        })
        void countsAreReadFromWordsAndDigits(String sentence, int count) {
            assertThat(goal(sentence)).isEqualTo(new Collect(Reference.to(Kind.BANANA), count));
        }

        @ParameterizedTest(name = "\"{0}\" collects all")
        @ValueSource(strings = {"collect all bananas", "collect all the bananas", "collect every banana",
            "collect each banana", "collect bananas", "collect the bananas", "collect as many bananas as you can"})
        void allEveryAndBarePluralsCollectAll(String sentence) {
            assertThat(goal(sentence)).isEqualTo(Collect.all(Reference.to(Kind.BANANA)));
        }

        @Test
        void aSuperlativePicksOneEvenInThePlural() {
            assertThat(goal("collect the nearest bananas"))
                    .isEqualTo(Collect.one(Reference.to(Kind.BANANA).withDistance(Distance.NEAREST)));
        }

        @Test
        void everythingIsAllFruit() {
            assertThat(goal("collect everything")).isEqualTo(Collect.all(Reference.to(Kind.FRUIT)));
        }

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = {"collect 0 bananas", "collect zero bananas", "collect 1.5 bananas",
            "collect 100000 bananas"})
        void impossibleCountsAreRefused(String sentence) {
            assertThat(refused(sentence).answer()).containsAnyOf("none", "whole", "'all'");
        }
    }

    @Nested
    class Sequences {

        private final Goal castleThenTomato = Sequence.of(new GoTo(Reference.to(Kind.CASTLE)),
                Collect.one(Reference.to(Kind.TOMATO)));

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = {
            "go to the castle and then pick up a tomato",
            "go to the castle then pick up a tomato",
            "go to the castle, then pick up a tomato",
            "go to the castle and pick up a tomato",
            "first go to the castle, then pick up a tomato",
            "go to the castle first, then pick up a tomato",
            "go to the castle. After that, pick up a tomato.",
            "go to the castle; afterwards pick up a tomato",
            "go to the castle, next pick up a tomato",
            "go to the castle and when you are done pick up a tomato",
            "pick up a tomato after going to the castle",
            "after going to the castle, pick up a tomato",
            "go to the castle before picking up a tomato",
            "before picking up a tomato, go to the castle",
            "go to the castle to pick up a tomato"})
        void areReadInTheOrderMeant(String sentence) {
            assertThat(goal(sentence)).isEqualTo(castleThenTomato);
        }

        @Test
        void aClauseWithoutAVerbBorrowsThePreviousOne() {
            assertThat(goal("pick up the banana, the tomato and the coconut")).isEqualTo(Sequence.of(
                    Collect.one(Reference.to(Kind.BANANA)), Collect.one(Reference.to(Kind.TOMATO)),
                    Collect.one(Reference.to(Kind.COCONUT))));
        }

        @Test
        void itRefersToWhatWasSaidBefore() {
            assertThat(goal("find a coconut and pick it up")).isEqualTo(Sequence.of(
                    new LookFor(Reference.to(Kind.COCONUT)), Collect.one(Reference.to(Kind.COCONUT))));
            assertThat(refused("pick it up").answer()).contains("What should I pick up?");
        }

        @Test
        void sequencesAreFlat() {
            Goal goal = goal("go north, then go to the table to pick up the banana, then come back");
            assertThat(goal).isInstanceOf(Sequence.class);
            assertThat(((Sequence) goal).steps()).hasSize(4).noneMatch(Sequence.class::isInstance);
        }
    }

    @Nested
    class Addressing {

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = {"Guppy, stop", "Guppy stop", "guppy: stop", "Hey Guppy, stop!", "stop, Guppy",
            "Stop Guppy", "ok guppy, please stop"})
        void theAddresseeIsParsedOffAndTheGoalKept(String sentence) {
            Understood understood = understood(sentence);
            assertThat(understood.goal()).isEqualTo(new Stop());
            assertThat(understood.addressee()).contains("Guppy");
            assertThat(understood.isFor("guppy")).isTrue();
            assertThat(understood.isFor("Bunny")).isFalse();
        }

        @Test
        void anUnaddressedSentenceIsForEveryone() {
            Understood understood = understood("stop");
            assertThat(understood.addressee()).isEmpty();
            assertThat(understood.isFor("Bunny")).isTrue();
        }

        @Test
        void anUnknownCapitalisedNameBeforeACommaIsAnAddressee() {
            assertThat(understood("Alice, go north").addressee()).contains("Alice");
        }

        @Test
        void theAddresseeIsKnownEvenWhenTheRestIsNotUnderstood() {
            NotUnderstood refusal = refused("Guppy, jump over the moon");
            assertThat(refusal.addressee()).contains("Guppy");
            assertThat(refusal.unknownWords()).containsExactly("jump", "moon");
        }

        @Test
        void aNameAfterFollowIsTheOneToFollowNotTheAddressee() {
            Understood understood = understood("Roadrunner, follow Bunny");
            assertThat(understood.addressee()).contains("Roadrunner");
            assertThat(understood.goal()).isEqualTo(Follow.agent("Bunny"));
        }
    }

    @Nested
    class Names {

        @Test
        void namesGivenAtConstructionAreKnownInAnyCaseAndSpelling() {
            InstructionInterpreter withAlice = new InstructionInterpreter(List.of("Alice", "Bartholomew"));
            assertThat(((Understood) withAlice.interpret("follow alice")).goal()).isEqualTo(Follow.agent("Alice"));
            assertThat(((Understood) withAlice.interpret("follow Bartholomeu")).goal())
                    .isEqualTo(Follow.agent("Bartholomew"));
        }

        @Test
        void anUnknownCapitalisedWordAfterFollowIsAName() {
            assertThat(goal("follow Zed")).isEqualTo(Follow.agent("Zed"));
        }

        @Test
        void anUnknownLowerCaseWordAfterFollowIsNamedAsUnknown() {
            assertThat(refused("follow zed").unknownWords()).containsExactly("zed");
        }

        @Test
        void thePapersAgentsAreKnownAlsoByWhatTheyAre() {
            assertThat(goal("follow the rabbit")).isEqualTo(Follow.agent("Bunny"));
            assertThat(goal("follow the road runner")).isEqualTo(Follow.agent("Roadrunner"));
        }
    }

    @Nested
    class References {

        @Test
        void placesAttachToTheNearestNoun() {
            Reference castle = Reference.to(Kind.CASTLE);
            Reference table = Reference.to(Kind.TABLE).withPlace(Place.of(Relation.NEAR, castle));
            Reference banana = Reference.to(Kind.BANANA).withPlace(Place.of(Relation.ON, table));
            assertThat(goal("pick up the banana on the table near the castle")).isEqualTo(Collect.one(banana));
        }

        @ParameterizedTest(name = "\"{0}\" is {1}")
        @CsvSource({
            "pick up the banana on the table, on(table)",
            "pick up the banana from the table, on(table)",
            "pick up the banana in the tree, in(tree)",
            "pick up the banana from the tree, in(tree)",
            "pick up the banana hanging on the tree, on(tree)",
            "pick up the banana under the tree, under(tree)",
            "pick up the banana beneath the tree, under(tree)",
            "pick up the banana on the ground, on-ground",
            "pick up the banana lying on the floor, on-ground",
            "pick up the banana near the castle, near(castle)",
            "pick up the banana by the river, near(river)",
            "pick up the banana next to the bridge, near(bridge)",
            "pick up the banana across the bridge, beyond(bridge)",
            "pick up the banana on the other side of the river, beyond(river)",
            "pick up the banana beyond the river, beyond(river)",
            "pick up the banana behind the castle, beyond(castle)",
            "pick up the banana on this side of the river, this-side-of(river)",
            "pick up the banana north of the castle, north-of(castle)",
            "pick up the banana to the south-west of the castle, south-west-of(castle)",
            "pick up the banana to the east, east-of(here)"
        })
        void placesAreRelationsToAnAnchor(String sentence, String place) {
            assertThat(goal(sentence).notation()).isEqualTo("collect(banana " + place + ")");
        }

        @ParameterizedTest(name = "\"{0}\" is {1}")
        @CsvSource({
            "go to the big tree, big tree",
            "go to the large tree, big tree",
            "go to the small tree, small tree",
            "go to the little tree, small tree",
            "go to the largest tree, largest tree",
            "go to the tallest tree, largest tree",
            "go to the smallest tree, smallest tree",
            "go to the nearest tree, nearest tree",
            "go to the closest tree, nearest tree",
            "go to the farthest tree, farthest tree",
            "go to the furthest tree, farthest tree",
            "go to the nearest big tree, nearest big tree"
        })
        void sizesAndDistancesAreKept(String sentence, String reference) {
            assertThat(goal(sentence).notation()).isEqualTo("go-to(" + reference + ")");
        }

        @Test
        void compassDirectionsAreTheProtocolsSectors() {
            assertThat(goal("go north-west")).isEqualTo(new Head(Sector.NORTH_WEST));
            assertThat(goal("head south east")).isEqualTo(new Head(Sector.SOUTH_EAST));
            assertThat(goal("face east")).isEqualTo(new Face(Sector.EAST));
        }

        @Test
        void synonymsAndInflectionsShareAMeaning() {
            Goal banana = Collect.one(Reference.to(Kind.BANANA));
            for (String verb : List.of("grab", "take", "fetch", "get", "collect", "eat", "pick up", "gather")) {
                assertThat(goal(verb + " a banana")).as(verb).isEqualTo(banana);
            }
            Goal castle = new GoTo(Reference.to(Kind.CASTLE));
            for (String verb : List.of("go", "walk", "run", "head", "move", "travel", "hurry")) {
                assertThat(goal(verb + " to the castle")).as(verb).isEqualTo(castle);
            }
        }
    }

    @Nested
    class Refusals {

        @Test
        void nonsenseGetsAHelpfulAnswerNamingTheUnknownWords() {
            NotUnderstood refusal = refused("jump over the moon");
            assertThat(refusal.answer()).isEqualTo("I didn't understand 'jump over the moon' (I don't know 'jump' "
                    + "or 'moon'); I can go to places, collect fruit, explore, follow, turn, stop.");
            assertThat(refusal.unknownWords()).containsExactly("jump", "moon");
        }

        @Test
        void anUnknownFruitIsNamedAndTheKnownFruitListed() {
            NotUnderstood refusal = refused("pick up the pineapple");
            assertThat(refusal.unknownWords()).containsExactly("pineapple");
            assertThat(refusal.answer()).contains("'pineapple'", "tomatoes, bananas and coconuts");
        }

        @Test
        void unknownWordsAreNamedAsWritten() {
            assertThat(refused("Pick up the Pineapple").unknownWords()).containsExactly("Pineapple");
        }

        @ParameterizedTest(name = "\"{0}\"")
        @CsvSource(delimiter = '|', value = {
            "go | Where should I go?",
            "pick up | What should I pick up?",
            "follow | Whom should I follow?",
            "follow me | whom to follow",
            "turn | Which way should I turn",
            "look | What should I look for?",
            "go there | where 'there' is",
            "the banana | What should I do with 'the banana'?",
            "pick up the castle | only pick up fruit",
            "follow the river | only follow other agents",
            "go to two trees | only one place at a time",
            "don't follow Guppy | rather than what not to do",
            "when you stop, turn left | I can act when I see something",
            "from now on explore the forest | I can keep from now on only rules",
            "you can follow Guppy again | I can lift a rule",
            "collect all the tomatoes on that table | which one you mean by 'that table'",
            "go to the second biggest tree | count things by how near"
        })
        void incompleteOrImpossibleInstructionsGetAQuestionOrAReason(String sentence, String answer) {
            NotUnderstood refusal = refused(sentence);
            assertThat(refusal.answer()).contains(answer);
            assertThat(refusal.unknownWords()).isEmpty();
        }

        @Test
        void emptyAndNullAskWhatToDo() {
            assertThat(refused("").answer()).startsWith("Tell me what to do");
            assertThat(refused("   ").answer()).startsWith("Tell me what to do");
            assertThat(interpreter.interpret(null)).isInstanceOf(NotUnderstood.class);
        }

        @Test
        void aVeryLongSentenceIsRefusedQuickly() {
            String sentence = "go to the castle and ".repeat(500) + "stop";
            NotUnderstood refusal = refused(sentence);
            assertThat(refusal.answer()).contains("too long");
        }

        @Test
        void theAnswerQuotesOnlyPrintableText() {
            NotUnderstood refusal = refused("jump\u0000\u0007 over\n the moon");
            assertThat(refusal.answer()).startsWith("I didn't understand 'jump over the moon'");
        }
    }

    @Nested
    class Restatements {

        @ParameterizedTest(name = "\"{0}\"")
        @CsvSource(delimiter = '|', value = {
            "get the nearest banana on a table | Going to pick up the nearest banana that lies on a table.",
            "go to the castle and then pick up a tomato | Going to the castle, then picking up a tomato.",
            "collect three bananas | Going to pick up three bananas.",
            "collect everything on the other side of the river | Going to pick up all the fruit on the other side "
                    + "of the river.",
            "eat the tomato under the tree | Going to pick up a tomato that lies under a tree.",
            "pick the coconut from the tree | Going to pick up a coconut that hangs in a tree.",
            "walk to the big tree by the river | Going to a big tree near the river.",
            "cross the bridge | Going to cross a bridge.",
            "go north | Heading north.",
            "come back | Coming back.",
            "turn left | Turning left.",
            "turn around | Turning around.",
            "turn 30 degrees to the right | Turning 30 degrees to the right.",
            "face west | Turning to face west.",
            "look for coconuts | Looking for coconuts.",
            "explore the forest | Exploring the forest.",
            "explore | Exploring.",
            "follow Roadrunner | Following Roadrunner.",
            "stop | Stopping.",
            "wait here | Waiting here.",
            "wait for two minutes | Waiting here for 2 minutes.",
            "carry on | Carrying on by myself.",
            "please fetch me the small banana first, then explore | Going to pick up a small banana, then exploring.",
            "go to the other side of the castle | Going to the other side of the castle."
        })
        void restateTheGoalInOneEnglishLine(String sentence, String restatement) {
            Understood understood = understood(sentence);
            assertThat(understood.restatement()).isEqualTo(restatement);
            assertThat(understood.goal().restatement()).isEqualTo(restatement);
        }
    }

    @Nested
    class Robustness {

        private static final String[] WORDS = {"go", "to", "the", "castle", "pick", "up", "banana", "bananas",
            "and", "then", "after", "before", "it", "them", "on", "in", "under", "near", "table", "tree", "north",
            "of", "left", "turn", "around", "3", "three", "all", "every", "everything", "nearest", "big", "follow",
            "Guppy", "Zed", "stop", "wait", "for", "seconds", "a", "an", "one", "ones", ",", ".", ":", "please",
            "across", "beyond", "other", "side", "this", "explore", "look", "search", "find", "back", "home",
            "here", "there", "me", "not", "don't", "take", "get", "cross", "bridge", "river", "degrees", "by",
            "face", "carry", "keep", "going", "do", "use", "with", "both", "some", "0", "2.5", "99999999999",
            "fruit", "world", "ground", "area", "place", "pineapple", "Alice", "twice", "bit", "all", "from"};

        @Test
        void randomSequencesOfKnownWordsNeverFail() {
            Random random = new Random(1998);
            for (int i = 0; i < 20_000; i++) {
                StringBuilder sentence = new StringBuilder();
                int length = 1 + random.nextInt(9);
                for (int w = 0; w < length; w++) {
                    sentence.append(WORDS[random.nextInt(WORDS.length)]).append(' ');
                }
                assertUnderstandsWithoutFailing(sentence.toString());
            }
        }

        @Test
        void randomCharactersNeverFail() {
            Random random = new Random(42);
            for (int i = 0; i < 2_000; i++) {
                StringBuilder sentence = new StringBuilder();
                int length = random.nextInt(60);
                for (int c = 0; c < length; c++) {
                    int codePoint = random.nextInt(4) == 0 ? random.nextInt(0x1FFFF) : 32 + random.nextInt(95);
                    if (Character.isValidCodePoint(codePoint) && !Character.isSurrogate((char) codePoint)) {
                        sentence.appendCodePoint(codePoint);
                    }
                }
                assertUnderstandsWithoutFailing(sentence.toString());
            }
        }

        @ParameterizedTest(name = "{index}")
        @ValueSource(strings = {"", " ", "\u0000", "\t\n\r", "🍌", "🍌 pick up 🍌", "\ud83c", "\u202e go north",
            "ＧＯ ＴＯ ＴＨＥ ＣＡＳＴＬＥ", "go to the castle\u0301\u0301", "...", ",,,", "'''", "---",
            "9999999999999999999999999 bananas", "collect 1e9 bananas", "turn NaN degrees", "a", "the", "and",
            "then then then", "after", "before", "it", "Guppy,", ", Guppy", ":", "Guppy Guppy Guppy"})
        void oddInputsNeverFail(String sentence) {
            assertUnderstandsWithoutFailing(sentence);
        }

        @Test
        void tenThousandCharactersNeverFail() {
            assertUnderstandsWithoutFailing("x".repeat(10_000));
            assertUnderstandsWithoutFailing("go ".repeat(3_333));
            assertUnderstandsWithoutFailing("\u0000".repeat(10_000));
        }

        @Test
        void theSafetyNetOfInterpretIsNotNeededButAnswersAnyway() {
            assertThat(interpreter.interpret("go to the castle")).isEqualTo(new Understood(
                    new GoTo(Reference.to(Kind.CASTLE)), "Going to the castle.", Optional.empty()));
        }

        private void assertUnderstandsWithoutFailing(String sentence) {
            Interpretation interpretation = interpreter.understand(sentence);
            assertThat(interpretation).as(sentence).isNotNull();
            if (interpretation instanceof Understood understood) {
                assertThat(understood.restatement()).as(sentence).isNotBlank();
                assertThat(understood.goal().notation()).as(sentence).isNotBlank();
                assertThat(GoalJson.write(understood.goal())).as(sentence).isNotBlank();
            } else {
                NotUnderstood refusal = (NotUnderstood) interpretation;
                assertThat(refusal.answer()).as(sentence).isNotBlank();
            }
        }
    }
}
