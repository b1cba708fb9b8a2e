package io.orchard.agents.language;

import java.util.List;

/** A cursor over the lexemes of one clause, for the grammar to read them one by one. */
final class Cursor {

    private final List<Lexeme> tokens;
    private int position;

    Cursor(List<Lexeme> tokens) {
        this.tokens = tokens;
    }

    boolean atEnd() {
        return position >= tokens.size();
    }

    int remaining() {
        return tokens.size() - position;
    }

    int position() {
        return position;
    }

    void seek(int position) {
        this.position = position;
    }

    Lexeme peek() {
        return peekAt(0);
    }

    Lexeme peekAt(int ahead) {
        int index = position + ahead;
        return index < tokens.size() ? tokens.get(index) : null;
    }

    boolean peekIs(Lexeme.Cat cat, String lemma) {
        Lexeme t = peek();
        return t != null && t.is(cat, lemma);
    }

    Lexeme next() {
        return tokens.get(position++);
    }

    List<Lexeme> rest() {
        return tokens.subList(position, tokens.size());
    }

    /** The words from {@code start} to the cursor, as written. */
    String rawSince(int start) {
        StringBuilder raw = new StringBuilder();
        String previous = null;
        for (Lexeme t : tokens.subList(start, position)) {
            if (!t.raw().equals(previous)) {
                raw.append(raw.length() == 0 ? "" : " ").append(t.raw());
            }
            previous = t.raw();
        }
        return raw.toString();
    }
}
