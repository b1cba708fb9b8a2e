package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Tokenizer.Token;
import io.orchard.agents.language.Tokenizer.Type;
import java.util.List;
import org.junit.jupiter.api.Test;

class TokenizerTest {

    private static List<String> texts(String sentence) {
        return Tokenizer.tokens(sentence).stream().map(Token::text).toList();
    }

    @Test
    void wordsComeOutInLowerCaseWithoutAccents() {
        assertThat(texts("Pick UP the Cóconut")).containsExactly("pick", "up", "the", "coconut");
    }

    @Test
    void punctuationSeparatesAndIsKeptAsMarks() {
        assertThat(texts("Guppy, stop; go north! now?")).containsExactly("guppy", ",", "stop", ",", "go", "north",
                ".", "now", ".");
        assertThat(Tokenizer.tokens("Bunny: go").get(1).type()).isEqualTo(Type.COLON);
    }

    @Test
    void contractionsAreSpeltOut() {
        assertThat(texts("don't move")).containsExactly("do", "not", "move");
        assertThat(texts("can't, won't, let's, it's, you're, I'd")).containsExactly("can", "not", ",", "will", "not",
                ",", "let", "us", ",", "it", "is", ",", "you", "are", ",", "i", "would");
        assertThat(texts("dont stop")).containsExactly("do", "not", "stop");
        assertThat(texts("don\u2019t")).containsExactly("do", "not");
    }

    @Test
    void aPossessiveIsTheName() {
        assertThat(texts("Guppy's banana")).containsExactly("guppy", "banana");
    }

    @Test
    void hyphensJoinWords() {
        assertThat(texts("go north-east, do a u-turn")).containsExactly("go", "northeast", ",", "do", "a", "uturn");
    }

    @Test
    void numbersKeepTheirDecimalsAndTheDegreeSignIsAWord() {
        assertThat(Tokenizer.tokens("turn 22.5° then 3.")).extracting(Token::text, Token::type).containsExactly(
                org.assertj.core.groups.Tuple.tuple("turn", Type.WORD),
                org.assertj.core.groups.Tuple.tuple("22.5", Type.NUMBER),
                org.assertj.core.groups.Tuple.tuple("degrees", Type.WORD),
                org.assertj.core.groups.Tuple.tuple("then", Type.WORD),
                org.assertj.core.groups.Tuple.tuple("3", Type.NUMBER),
                org.assertj.core.groups.Tuple.tuple(".", Type.FULL_STOP));
    }

    @Test
    void emojiSymbolsAndControlCharactersAreDropped() {
        assertThat(texts("go\u0000 to\t the 🏰 castle\u0007 #@$")).containsExactly("go", "to", "the", "castle");
        assertThat(texts("🍌🍌")).isEmpty();
    }

    @Test
    void wordsRememberHowTheyWereWritten() {
        Token token = Tokenizer.tokens("Follow Roadrunner").get(1);
        assertThat(token.raw()).isEqualTo("Roadrunner");
        assertThat(token.capitalised()).isTrue();
        assertThat(Tokenizer.tokens("follow").get(0).capitalised()).isFalse();
    }
}
