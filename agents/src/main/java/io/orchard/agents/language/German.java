package io.orchard.agents.language;

import static io.orchard.agents.language.Lexeme.Cat.AGAIN;
import static io.orchard.agents.language.Lexeme.Cat.COND;
import static io.orchard.agents.language.Lexeme.Cat.CONN;
import static io.orchard.agents.language.Lexeme.Cat.DIR;
import static io.orchard.agents.language.Lexeme.Cat.LASTING;
import static io.orchard.agents.language.Lexeme.Cat.ME;
import static io.orchard.agents.language.Lexeme.Cat.NEG;
import static io.orchard.agents.language.Lexeme.Cat.ONLY;
import static io.orchard.agents.language.Lexeme.Cat.PERMIT;
import static io.orchard.agents.language.Lexeme.Cat.PREP;
import static io.orchard.agents.language.Lexeme.Cat.PUNCT;
import static io.orchard.agents.language.Lexeme.Cat.SIDE;
import static io.orchard.agents.language.Lexeme.Cat.VERB;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * German word order made into the order the grammar reads: German puts words where English does not,
 * and the grammar of goals is read from English order. Before the words are looked up, contractions
 * are split ("zum" is "zu dem") and relative clauses joined to their noun ("die Banane, die dem
 * Schloss am nächsten ist" is "die Banane am nächsten zu dem Schloss"); after, in each clause, the
 * infinitive a modal verb left at the end comes first ("kannst du zum Schloss gehen"), a separable
 * particle joins its verb ("heb die Kokosnuss auf", "komm zu mir zurück"), "nicht" and "kein" go
 * before the verb ("geh nicht in die Nähe des Flusses"), "dann" before it ("dreh dich dann nach
 * links"), and a condition ends with what it sees ("wenn du eine Banane siehst, ...").
 */
final class German {

    private static final Map<String, List<String>> CONTRACTIONS = Map.ofEntries(
            Map.entry("zum", List.of("zu", "dem")), Map.entry("zur", List.of("zu", "der")),
            Map.entry("im", List.of("in", "dem")), Map.entry("am", List.of("an", "dem")),
            Map.entry("vom", List.of("von", "dem")), Map.entry("beim", List.of("bei", "dem")),
            Map.entry("ins", List.of("in", "das")), Map.entry("ans", List.of("an", "das")),
            Map.entry("aufs", List.of("auf", "das")), Map.entry("ubers", List.of("uber", "das")),
            Map.entry("uebers", List.of("ueber", "das")), Map.entry("durchs", List.of("durch", "das")),
            Map.entry("hinters", List.of("hinter", "das")), Map.entry("unterm", List.of("unter", "dem")));

    private static final Set<String> RELATIVE = Set.of("der", "die", "das", "welche", "welcher", "welches", "den");
    private static final Set<String> BEING = Set.of("ist", "sind", "liegt", "liegen", "steht", "stehen", "hangt",
            "hangen", "haengt", "haengen", "befindet", "befinden", "wachst", "waechst");

    private German() {
    }

    /** The tokens with contractions split, commas before "wo" and "was" dropped and relative clauses joined. */
    static List<Tokenizer.Token> tokens(List<Tokenizer.Token> tokens) {
        List<Tokenizer.Token> split = new ArrayList<>();
        for (int i = 0; i < tokens.size(); i++) {
            Tokenizer.Token token = tokens.get(i);
            Tokenizer.Token next = i + 1 < tokens.size() ? tokens.get(i + 1) : null;
            if (token.isPunctuation() && !token.text().equals(".") && next != null && next.isWord()
                    && (next.text().equals("wo") || next.text().equals("was"))) {
                continue; // "mach, was du willst", "geh dorthin zurück, wo du angefangen hast"
            }
            List<String> parts = token.isWord() ? CONTRACTIONS.get(token.text()) : null;
            if (parts == null) {
                split.add(token);
            } else {
                for (String part : parts) {
                    split.add(new Tokenizer.Token(part, token.raw(), Tokenizer.Type.WORD, token.capitalised()));
                }
            }
        }
        return relativeClauses(split);
    }

    /**
     * ", die dem Schloss am nächsten ist" after a noun: the relative pronoun, the comma and the verb of
     * being go, and "am nächsten" ("am weitesten") comes first with "zu": "am nächsten zu dem Schloss".
     */
    private static List<Tokenizer.Token> relativeClauses(List<Tokenizer.Token> tokens) {
        List<Tokenizer.Token> out = new ArrayList<>(tokens);
        for (int i = 0; i + 1 < out.size(); i++) {
            Tokenizer.Token comma = out.get(i);
            Tokenizer.Token pronoun = out.get(i + 1);
            if (!comma.isPunctuation() || comma.text().equals(".") || !pronoun.isWord()
                    || !RELATIVE.contains(pronoun.text())) {
                continue;
            }
            int end = i + 2;
            while (end < out.size() && !out.get(end).isPunctuation()) {
                end++;
            }
            Tokenizer.Token last = out.get(end - 1);
            if (end - 1 <= i + 1 || !last.isWord() || !BEING.contains(last.text())) {
                continue;
            }
            List<Tokenizer.Token> clause = new ArrayList<>(out.subList(i + 2, end - 1));
            int at = clause.size() - 3; // "an dem nächsten", as "am nächsten" was split
            if (at > 0 && clause.get(at).text().equals("an") && clause.get(at + 1).text().equals("dem")
                    && clause.get(at + 2).isWord() && (clause.get(at + 2).text().startsWith("nachst")
                    || clause.get(at + 2).text().startsWith("naechst"))) {
                List<Tokenizer.Token> superlative = new ArrayList<>(clause.subList(at, at + 3));
                superlative.add(new Tokenizer.Token("zu", "zu", Tokenizer.Type.WORD, false));
                superlative.addAll(clause.subList(0, at));
                clause = superlative;
            }
            List<Tokenizer.Token> joined = new ArrayList<>(out.subList(0, i));
            joined.addAll(clause);
            joined.addAll(out.subList(end, out.size()));
            return relativeClauses(joined);
        }
        return out;
    }

    /** The lexemes in the order the grammar reads. */
    static List<Lexeme> lexemes(List<Lexeme> lexemes) {
        List<Lexeme> moved = thenFirst(new ArrayList<>(lexemes));
        List<Lexeme> out = new ArrayList<>();
        int start = 0;
        for (int i = 0; i <= moved.size(); i++) {
            if (i == moved.size() || moved.get(i).is(PUNCT) || moved.get(i).is(CONN)) {
                out.addAll(clause(new ArrayList<>(moved.subList(start, i))));
                if (i < moved.size()) {
                    out.add(moved.get(i));
                }
                start = i + 1;
            }
        }
        return out;
    }

    /** "nimm dann eine Tomate": "dann" before its verb. */
    private static List<Lexeme> thenFirst(List<Lexeme> lexemes) {
        for (int i = 1; i < lexemes.size(); i++) {
            Lexeme then = lexemes.get(i);
            if (then.is(CONN, "then") && lexemes.get(i - 1).is(VERB)
                    && (i == 1 || lexemes.get(i - 2).is(PUNCT) || lexemes.get(i - 2).is(CONN))) {
                lexemes.set(i, lexemes.get(i - 1));
                lexemes.set(i - 1, then);
            }
        }
        return lexemes;
    }

    private static List<Lexeme> clause(List<Lexeme> words) {
        if (words.isEmpty()) {
            return words;
        }
        condition(words);
        int head = 0;
        while (head < words.size() && (words.get(head).is(PERMIT) || words.get(head).is(AGAIN)
                || words.get(head).is(LASTING) || words.get(head).is(NEG) || words.get(head).is(ONLY)
                || words.get(head).is(COND))) {
            head++;
        }
        if (head < words.size() - 1 && !words.get(head).is(VERB) && words.get(words.size() - 1).is(VERB)) {
            words.add(head, words.remove(words.size() - 1)); // "kannst du zum Schloss gehen"
        }
        if (head < words.size() && words.get(head).is(VERB)) {
            particle(words, head);
            negation(words, head);
            bring(words, head);
        }
        for (int i = words.size() - 2; i >= 0; i--) {
            if (words.get(i).is(PREP, "to") && words.get(i).raw().equalsIgnoreCase("nach")
                    && (words.get(i + 1).is(DIR) || words.get(i + 1).is(SIDE)) && i > 0
                    && words.get(i - 1).isAny(VERB, "look", "turn", "face")) {
                words.remove(i); // "schau nach Norden", as "look north"
            }
        }
        return words;
    }

    /** "wenn du eine Banane siehst": a condition on what is seen ends with the seeing. */
    private static void condition(List<Lexeme> words) {
        Lexeme first = words.get(0);
        Lexeme last = words.get(words.size() - 1);
        if (first.is(COND, "when") && words.size() > 2 && last.is(VERB, "see")) {
            words.set(0, new Lexeme(COND, "when-see", false, 0, first.raw(), first.capitalised(), null,
                    first.position()));
            words.remove(words.size() - 1);
        }
    }

    /** A separable particle at the end of the clause joins the verb: "komm zu mir zurück", "heb ... auf". */
    private static void particle(List<Lexeme> words, int verbAt) {
        if (words.size() - verbAt < 2) {
            return;
        }
        Lexeme verb = words.get(verbAt);
        Lexeme last = words.get(words.size() - 1);
        if (!last.is(PREP)) {
            return;
        }
        String lemma = verb.lemma();
        switch (last.lemma()) {
            case "back", "at", "around" -> {
                if (last.is(PREP, "at") && !lemma.equals("look")) {
                    return;
                }
                if (last.is(PREP, "around") && !(lemma.equals("turn") || lemma.equals("look"))) {
                    return;
                }
                words.remove(words.size() - 1);
                words.add(verbAt + 1, last); // "schau das Schloss an": "look at the castle"
            }
            case "on" -> {
                if (lemma.equals("pick") || lemma.equals("collect") || lemma.equals("take")) {
                    words.remove(words.size() - 1); // "heb die Kokosnuss auf": pick it up
                }
            }
            case "after" -> {
                if (lemma.equals("go") || lemma.equals("come")) {
                    words.remove(words.size() - 1);
                    words.set(verbAt, as(verb, VERB, "follow")); // "lauf Guppy hinterher"
                }
            }
            case "away" -> {
                if (lemma.equals("keep") || lemma.equals("wait")) {
                    words.remove(words.size() - 1); // "halte dich vom Fluss fern": keep away from it
                    if (words.size() > verbAt + 1 && words.get(verbAt + 1).is(PREP, "from")) {
                        words.remove(verbAt + 1);
                    }
                    words.set(verbAt, as(verb, VERB, "avoid"));
                    words.add(verbAt + 1, as(last, PREP, "near"));
                }
            }
            default -> {
                // a preposition that ends the clause is its own
            }
        }
    }

    /** "geh nicht ...", "überquere den Fluss nicht", "iss keine Tomaten": the negation before the verb. */
    private static void negation(List<Lexeme> words, int verbAt) {
        for (int i = verbAt + 1; i < words.size(); i++) {
            if (words.get(i).is(NEG)) {
                Lexeme not = words.remove(i);
                words.add(verbAt, not);
                return;
            }
        }
    }

    /** "bring sie mir": bring it to me. */
    private static void bring(List<Lexeme> words, int verbAt) {
        Lexeme verb = words.get(verbAt);
        Lexeme last = words.get(words.size() - 1);
        if (verb.is(VERB, "collect") && verb.raw().toLowerCase(java.util.Locale.ROOT).startsWith("bring")
                && last.is(ME) && words.size() - verbAt > 2 && !words.get(words.size() - 2).is(PREP, "to")) {
            words.add(words.size() - 1, as(last, PREP, "to"));
        }
    }

    private static Lexeme as(Lexeme word, Lexeme.Cat cat, String lemma) {
        return new Lexeme(cat, lemma, false, 0, word.raw(), word.capitalised(), word.corrected(), word.position());
    }
}
