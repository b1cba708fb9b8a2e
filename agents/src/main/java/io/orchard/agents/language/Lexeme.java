package io.orchard.agents.language;

/**
 * A word (or a phrase read as one word) of a sentence, as the grammar sees it: its category and
 * lemma after spelling correction, synonyms and phrases.
 *
 * @param cat         the category
 * @param lemma       the canonical word: {@code collect} for "grab", {@code banana} for "bananas",
 *                    {@code near} for "next to"; the word itself when unknown
 * @param plural      whether a noun was plural
 * @param number      the value of a number
 * @param raw         the text as written, to name it in answers and to keep a name's spelling
 * @param capitalised whether it was written with a capital first letter
 * @param corrected   the words as written that were taken for known words they were not spelt as
 *                    (for a phrase, only those of its words); null when none were
 * @param position    its index among the sentence's tokens, to tell equal words apart
 */
record Lexeme(Cat cat, String lemma, boolean plural, double number, String raw, boolean capitalised,
              String corrected, int position) {

    /** The categories of the grammar. */
    enum Cat {
        VERB, NOUN, NAME, SIZE, DIST, NUMBER, QUANT, DET, PREP, DIR, SIDE, UNIT, HERE, PRON, ME, CONN, NEG,
        FILLER, PUNCT, UNKNOWN,
        /** A condition: {@code when-see} ("when you see", "if you find"), or a bare "when", "if". */
        COND,
        /** "only", "nothing but": the only fruit to take. */
        ONLY,
        /** "from now on", "for the rest of the game": a rule that lasts. */
        LASTING,
        /** "again": with {@link #PERMIT}, a rule lifted. */
        AGAIN,
        /** "you can", "you may", "feel free to": with {@link #AGAIN}, a rule lifted. */
        PERMIT,
        /** "rule", "rules", "restrictions". */
        RULE,
        /** An ordinal: "second", "third", "4th"; its value is the number. */
        ORD
    }

    boolean is(Cat cat) {
        return this.cat == cat;
    }

    boolean is(Cat cat, String lemma) {
        return this.cat == cat && this.lemma.equals(lemma);
    }

    boolean isAny(Cat cat, String... lemmas) {
        if (this.cat != cat) {
            return false;
        }
        for (String candidate : lemmas) {
            if (lemma.equals(candidate)) {
                return true;
            }
        }
        return false;
    }
}
