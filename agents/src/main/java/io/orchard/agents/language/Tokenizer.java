package io.orchard.agents.language;

import java.text.Normalizer;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Splits a sentence into words, numbers and punctuation marks. Words come out in lower case
 * without accents or hyphens ("North-East" becomes {@code northeast}); contractions are spelt out
 * ("don't" becomes {@code do not}); symbols other than punctuation, emoji and control characters
 * are dropped. Each word keeps the text it was written as, to name it in answers.
 */
final class Tokenizer {

    /** What a token is. */
    enum Type { WORD, NUMBER, COMMA, COLON, FULL_STOP }

    /**
     * One token.
     *
     * @param text        the normalised word, the number's digits, or the punctuation mark
     * @param raw         the text as written
     * @param type        what it is
     * @param capitalised whether it was written with a capital first letter
     */
    record Token(String text, String raw, Type type, boolean capitalised) {

        boolean isWord() {
            return type == Type.WORD;
        }

        boolean isPunctuation() {
            return type == Type.COMMA || type == Type.COLON || type == Type.FULL_STOP;
        }
    }

    /** Contractions written without an apostrophe, spelt out. */
    private static final Map<String, String> BARE_CONTRACTIONS = Map.ofEntries(
            Map.entry("dont", "do not"), Map.entry("doesnt", "does not"), Map.entry("cant", "can not"),
            Map.entry("cannot", "can not"), Map.entry("wont", "will not"), Map.entry("lets", "let us"),
            Map.entry("youre", "you are"), Map.entry("thats", "that is"), Map.entry("im", "i am"),
            Map.entry("ive", "i have"), Map.entry("youve", "you have"), Map.entry("id", "i would"),
            Map.entry("gonna", "going to"), Map.entry("wanna", "want to"), Map.entry("gotta", "got to"));

    private Tokenizer() {
    }

    static List<Token> tokens(String sentence) {
        return tokens(sentence, Language.ENGLISH);
    }

    /** The tokens of a sentence in this language: English contractions are spelt out only in English. */
    static List<Token> tokens(String sentence, Language language) {
        boolean english = language == Language.ENGLISH;
        String text = Normalizer.normalize(sentence, Normalizer.Form.NFKC);
        List<Token> tokens = new ArrayList<>();
        int i = 0;
        while (i < text.length()) {
            int c = text.codePointAt(i);
            if (Character.isLetter(c)) {
                int end = wordEnd(text, i);
                addWord(text.substring(i, end), tokens, english);
                i = end;
            } else if (Character.isDigit(c)) {
                int end = numberEnd(text, i);
                String digits = text.substring(i, end);
                tokens.add(new Token(asciiDigits(digits), digits, Type.NUMBER, false));
                i = end;
            } else {
                addSymbol(c, tokens);
                i += Character.charCount(c);
            }
        }
        return tokens;
    }

    /** The end of the word at {@code start}: letters, with apostrophes and hyphens between letters. */
    private static int wordEnd(String text, int start) {
        int i = start;
        while (i < text.length()) {
            int c = text.codePointAt(i);
            if (Character.isLetter(c) || Character.getType(c) == Character.NON_SPACING_MARK) {
                i += Character.charCount(c);
            } else if ((isApostrophe(c) || isHyphen(c)) && i + 1 < text.length()
                    && Character.isLetter(text.codePointAt(i + 1))) {
                i += Character.charCount(c);
            } else {
                break;
            }
        }
        return i;
    }

    /** The end of the number at {@code start}: digits, with at most one decimal point between digits. */
    private static int numberEnd(String text, int start) {
        int i = start;
        boolean point = false;
        while (i < text.length()) {
            int c = text.codePointAt(i);
            if (Character.isDigit(c)) {
                i += Character.charCount(c);
            } else if (c == '.' && !point && i + 1 < text.length() && Character.isDigit(text.codePointAt(i + 1))) {
                point = true;
                i++;
            } else {
                break;
            }
        }
        return i;
    }

    /** The number's digits in ASCII, whatever script they were written in. */
    private static String asciiDigits(String number) {
        StringBuilder digits = new StringBuilder(number.length());
        number.codePoints().forEach(c -> digits.append(c == '.' ? '.'
                : Character.forDigit(Character.digit(c, 10), 10)));
        return digits.toString();
    }

    private static void addSymbol(int c, List<Token> tokens) {
        String raw = new String(Character.toChars(c));
        switch (c) {
            case ',', ';' -> tokens.add(new Token(",", raw, Type.COMMA, false));
            case ':' -> tokens.add(new Token(":", raw, Type.COLON, false));
            case '.', '!', '?', '\u2026' -> tokens.add(new Token(".", raw, Type.FULL_STOP, false));
            case '&', '+' -> tokens.add(new Token("and", raw, Type.WORD, false));
            case '\u00b0' -> tokens.add(new Token("degrees", raw, Type.WORD, false));
            default -> {
                // other symbols, emoji and control characters carry no instruction
            }
        }
    }

    private static void addWord(String raw, List<Token> tokens, boolean english) {
        boolean capitalised = Character.isUpperCase(raw.codePointAt(0));
        String word = stripAccents(raw).toLowerCase(Locale.ROOT);
        StringBuilder plain = new StringBuilder(word.length());
        for (int i = 0; i < word.length(); i++) {
            char c = word.charAt(i);
            if (isApostrophe(c)) {
                plain.append('\'');
            } else if (!isHyphen(c)) {
                plain.append(c);
            }
        }
        for (String part : (english ? spellOut(plain.toString()) : plain.toString().replace("'", "")).split(" ")) {
            if (!part.isEmpty()) {
                tokens.add(new Token(part, raw, Type.WORD, capitalised));
            }
        }
    }

    /** Spells out contractions: "don't" is "do not", "let's" is "let us", "guppy's" is "guppy". */
    private static String spellOut(String word) {
        String bare = BARE_CONTRACTIONS.get(word);
        if (bare != null) {
            return bare;
        }
        int apostrophe = word.indexOf('\'');
        if (apostrophe < 0) {
            return word;
        }
        String stem = word.substring(0, apostrophe);
        String ending = word.substring(apostrophe + 1).replace("'", "");
        if (ending.equals("t") && stem.endsWith("n")) {
            String verb = stem.substring(0, stem.length() - 1);
            return switch (verb) {
                case "ca" -> "can not";
                case "wo" -> "will not";
                case "sha" -> "shall not";
                default -> verb + " not";
            };
        }
        return switch (ending) {
            case "s" -> stem.equals("let") ? "let us" : isPronounWithIs(stem) ? stem + " is" : stem;
            case "re" -> stem + " are";
            case "ll" -> stem + " will";
            case "ve" -> stem + " have";
            case "d" -> stem + " would";
            case "m" -> stem + " am";
            default -> stem + ending;
        };
    }

    private static boolean isPronounWithIs(String stem) {
        return switch (stem) {
            case "it", "that", "what", "there", "here", "he", "she", "who", "where" -> true;
            default -> false;
        };
    }

    private static String stripAccents(String word) {
        String decomposed = Normalizer.normalize(word, Normalizer.Form.NFD);
        StringBuilder plain = new StringBuilder(decomposed.length());
        decomposed.codePoints()
                .filter(c -> Character.getType(c) != Character.NON_SPACING_MARK)
                .forEach(plain::appendCodePoint);
        return plain.toString();
    }

    private static boolean isApostrophe(int c) {
        return c == '\'' || c == '\u2019' || c == '\u2018' || c == '`' || c == '\u00b4';
    }

    private static boolean isHyphen(int c) {
        return c == '-' || c == '\u2010' || c == '\u2011' || c == '\u2013';
    }
}
