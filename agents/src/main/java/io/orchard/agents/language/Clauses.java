package io.orchard.agents.language;

import static io.orchard.agents.language.Lexeme.Cat.COND;
import static io.orchard.agents.language.Lexeme.Cat.CONN;
import static io.orchard.agents.language.Lexeme.Cat.ME;
import static io.orchard.agents.language.Lexeme.Cat.PREP;
import static io.orchard.agents.language.Lexeme.Cat.PUNCT;
import static io.orchard.agents.language.Lexeme.Cat.VERB;

import java.util.ArrayList;
import java.util.List;

/**
 * The structure of a sentence: its clauses, split at punctuation, connectives ("and", "then",
 * "after that") and conditions ("when you see"), put in the order meant ("X after Y-ing" is Y, then X; "before Y-ing, X" is X,
 * then Y), without a bare "go" before another verb ("go and get the banana"), and the verb a
 * clause without one borrows from the clause before ("pick up the banana and the coconut").
 */
final class Clauses {

    private Clauses() {
    }

    /** How a clause is joined to the one before it. */
    enum Marker { NONE, AFTER, BEFORE }

    /**
     * A clause of the sentence.
     *
     * @param tokens    its lexemes, not empty
     * @param andJoined whether only "and" joined it to the clause before (so a lone name is an object)
     * @param marker    whether it was introduced by "after" or "before"
     */
    record Segment(List<Lexeme> tokens, boolean andJoined, Marker marker) {
    }

    /** The clauses of a sentence, in the order written. */
    static List<Segment> split(List<Lexeme> lexemes) {
        List<Segment> segments = new ArrayList<>();
        List<Lexeme> current = new ArrayList<>();
        boolean sawConnective = false;
        boolean onlyAnd = true;
        Marker marker = Marker.NONE;
        for (int i = 0; i < lexemes.size(); i++) {
            Lexeme t = lexemes.get(i);
            boolean subordinate = t.isAny(PREP, "after", "before") && i + 1 < lexemes.size()
                    && lexemes.get(i + 1).is(VERB);
            if (t.is(COND) && !current.isEmpty()) {
                // "take the bananas when you see them": the condition is a clause of its own
                segments.add(new Segment(List.copyOf(current), sawConnective && onlyAnd && !segments.isEmpty(), marker));
                current.clear();
                sawConnective = false;
                onlyAnd = true;
                marker = Marker.NONE;
            }
            if (t.is(PUNCT) || t.is(CONN) || subordinate) {
                if (!current.isEmpty()) {
                    segments.add(new Segment(List.copyOf(current), sawConnective && onlyAnd && !segments.isEmpty(),
                            marker));
                    current.clear();
                    sawConnective = false;
                    onlyAnd = true;
                    marker = Marker.NONE;
                }
                if (subordinate) {
                    marker = t.lemma().equals("after") ? Marker.AFTER : Marker.BEFORE;
                } else {
                    sawConnective = true;
                    onlyAnd &= t.is(CONN, "and");
                }
            } else {
                current.add(t);
            }
        }
        if (!current.isEmpty()) {
            segments.add(new Segment(List.copyOf(current), sawConnective && onlyAnd && !segments.isEmpty(), marker));
        }
        return segments;
    }

    /** "Y after X-ing" is X, then Y; "before X-ing, Y" is Y, then X. */
    static List<Segment> ordered(List<Segment> segments) {
        List<Segment> ordered = new ArrayList<>(segments);
        for (int i = 0; i < ordered.size(); i++) {
            Marker marker = ordered.get(i).marker();
            if (marker == Marker.AFTER && i > 0) {
                ordered.add(i - 1, ordered.remove(i));
            } else if (marker == Marker.BEFORE && i == 0 && ordered.size() > 1) {
                ordered.add(1, ordered.remove(0));
                i++;
            }
        }
        return ordered;
    }

    /** "go and get the banana": the bare "go" before another verb says nothing. */
    static List<Segment> withoutBareMotion(List<Segment> segments) {
        List<Segment> kept = new ArrayList<>();
        for (int i = 0; i < segments.size(); i++) {
            List<Lexeme> tokens = segments.get(i).tokens();
            boolean bare = tokens.size() == 1 && tokens.get(0).isAny(VERB, "go", "come");
            if (!(bare && i + 1 < segments.size() && segments.get(i + 1).tokens().get(0).is(VERB))) {
                kept.add(segments.get(i));
            }
        }
        return kept;
    }

    /** The verb of a clause with its particles ("pick up", "go to", "look for"), for clauses without one. */
    static List<Lexeme> prefixOf(List<Lexeme> tokens) {
        if (!tokens.get(0).is(VERB)) {
            return List.of();
        }
        int end = 1;
        while (end < tokens.size() && ((tokens.get(end).is(PREP) && !tokens.get(end).is(PREP, "of"))
                || tokens.get(end).is(ME))) {
            end++;
        }
        return List.copyOf(tokens.subList(0, end));
    }
}
