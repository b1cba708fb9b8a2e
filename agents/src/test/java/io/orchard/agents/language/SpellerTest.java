package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SpellerTest {

    @Nested
    class Distance {

        @ParameterizedTest(name = "{0} -> {1}: {2}")
        @CsvSource({
            "banana, banana, 0",
            "bananna, banana, 1",
            "banan, banana, 1",
            "bonana, banana, 1",
            "tabel, table, 1",
            "nroth, north, 1",
            "tomatoe, tomato, 1",
            "cocnut, coconut, 1",
            "roadruner, roadrunner, 1",
            "bannnanna, banana, 3"
        })
        void countsInsertionsDeletionsChangesAndSwaps(String a, String b, int expected) {
            assertThat(Speller.distance(a, b, 5)).isEqualTo(expected);
        }

        @Test
        void stopsAtTheLimit() {
            assertThat(Speller.distance("pineapple", "banana", 2)).isEqualTo(3);
        }
    }

    @Nested
    class WithTheVocabulary {

        private final Lexicon lexicon = Lexicon.withAgents(List.of(), Language.ENGLISH);

        @ParameterizedTest(name = "{0} -> {1}")
        @CsvSource({
            "bananna, banana",
            "castel, castle",
            "brige, bridge",
            "cocnut, coconut",
            "folow, follow",
            "explor, explore",
            "lfet, left",
            "rigth, right",
            "nearst, nearest",
            "roadruner, roadrunner",
            "colect, collect"
        })
        void correctsSmallTypos(String typo, String word) {
            assertThat(lexicon.correct(typo)).isEqualTo(word);
        }

        @Test
        void prefersAWordWithTheSameFirstLetter() {
            assertThat(lexicon.correct("trun")).isEqualTo("turn"); // not "run"
        }

        @Test
        void neverCorrectsWordsOfFewerThanFourLetters() {
            assertThat(lexicon.correct("tre")).isNull();
            assertThat(lexicon.correct("pik")).isNull();
        }

        @Test
        void allowsOneEditBelowSevenLettersAndTwoFromSeven() {
            assertThat(lexicon.correct("bnaana")).isEqualTo("banana"); // one swap
            assertThat(lexicon.correct("bnaanaa")).isEqualTo("banana"); // 7 letters, two edits
            assertThat(lexicon.correct("cstel")).isNull(); // 5 letters, two edits from "castle"
        }

        @Test
        void leavesUnknownWordsAlone() {
            assertThat(lexicon.correct("pineapple")).isNull();
            assertThat(lexicon.correct("moon")).isNull();
        }
    }

    @Nested
    class Ambiguity {

        @Test
        void aTypoAsCloseToTwoWordsOfDifferentMeaningsIsNotCorrected() {
            Speller speller = new Speller(Map.of("bake", "VERB:bake", "cake", "NOUN:cake"));
            assertThat(speller.correct("dake")).isNull();
        }

        @Test
        void twoFormsOfOneWordAreNotAnAmbiguity() {
            Speller speller = new Speller(Map.of("banana", "NOUN:banana", "bananas", "NOUN:banana"));
            assertThat(speller.correct("bananaa")).isEqualTo("banana");
            assertThat(speller.correct("bananaas")).isEqualTo("bananas");
        }

        @Test
        void aKnownWordIsNeverCorrectedIntoAnother() {
            Speller speller = new Speller(Map.of("tree", "NOUN:tree", "three", "NUMBER:3"));
            assertThat(speller.correct("tree")).isNull();
            assertThat(speller.correct("three")).isNull();
        }
    }

    @Nested
    class AcrossLanguages {

        private final Lexicon english = Lexicon.withAgents(List.of(), Language.ENGLISH);
        private final Lexicon german = Lexicon.withAgents(List.of(), Language.GERMAN);

        /** What the lexicon makes of one word: the word it was corrected into, or null when it was not corrected. */
        private String correction(Lexicon lexicon, String word) {
            List<Lexeme> read = lexicon.read(Tokenizer.tokens(word, lexicon.language()));
            return read.stream().filter(lexeme -> lexeme.corrected() != null).map(Lexeme::lemma).findFirst()
                    .orElse(null);
        }

        @Test
        void noGermanWordIsCorrectedIntoAnEnglishOne() {
            List<String> corrected = new ArrayList<>();
            GermanWords words = new GermanWords().build();
            for (String word : words.words().keySet()) {
                String into = correction(english, word);
                if (into != null) {
                    corrected.add(word + " -> " + into);
                }
            }
            assertThat(words.words()).hasSizeGreaterThan(400);
            assertThat(corrected).as("German words the English speller corrected").isEmpty();
        }

        @Test
        void noEnglishWordIsCorrectedIntoAGermanOne() {
            List<String> corrected = new ArrayList<>();
            for (String sentence : List.of("go to the castle and pick up the nearest banana on the table",
                    "walk north, then turn left and follow Guppy", "take three tomatoes from the ground",
                    "explore the forest until you find a coconut", "stop", "wait here for ten seconds",
                    "leave the coconuts alone", "the tree on your left", "this these that those then there")) {
                for (String word : sentence.split("[ ,]+")) {
                    String into = correction(german, word);
                    if (into != null) {
                        corrected.add(word + " -> " + into);
                    }
                }
            }
            assertThat(corrected).as("English words the German speller corrected").isEmpty();
        }

        @ParameterizedTest(name = "\"{0}\" is {1} in German, and not corrected in English")
        @CsvSource({"bananen, banana", "tisch, table", "baume, tree", "nimm, take", "brucke, bridge",
            "kokosnusse, coconut", "wald, forest"})
        void germanWordsAreKnownInGermanAndLeftAloneInEnglish(String word, String lemma) {
            Lexeme read = german.read(Tokenizer.tokens(word, Language.GERMAN)).get(0);
            assertThat(read.lemma()).isEqualTo(lemma);
            assertThat(correction(english, word)).isNull();
        }

        @Test
        void eachLanguageStillCorrectsItsOwnTypos() {
            assertThat(correction(english, "bananna")).isEqualTo("banana");
            assertThat(correction(german, "banahne")).isEqualTo("banana");
            assertThat(correction(german, "schlos")).isEqualTo("castle");
        }
    }
}
