package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

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

        private final Lexicon lexicon = Lexicon.withAgents(List.of());

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
}
