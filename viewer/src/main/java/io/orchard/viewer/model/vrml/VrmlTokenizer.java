package io.orchard.viewer.model.vrml;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import java.util.ArrayList;
import java.util.List;

/**
 * Splits VRML97 text into tokens: numbers, strings, identifiers and the four brackets, skipping
 * white space, commas and {@code #} comments. X3D attribute values use the same lexical rules
 * for numbers and quoted strings, so the XML parser tokenizes them here too.
 *
 * <p>A word that is neither a number nor a valid identifier becomes an {@link Type#INVALID} token
 * rather than an immediate error, so the parser can say which field it was meant for.
 */
final class VrmlTokenizer {

    enum Type { NUMBER, STRING, IDENT, OPEN_BRACE, CLOSE_BRACE, OPEN_BRACKET, CLOSE_BRACKET,
        PERIOD, INVALID, EOF }

    /**
     * One token. The location is kept as numbers and formatted only when a message needs it;
     * a fragment's tokens carry the fragment's location instead.
     */
    record Token(Type type, String text, int line, int column, String fixedLocation) {

        Token(Type type, String text, String location) {
            this(type, text, 0, 0, location);
        }

        String location() {
            return fixedLocation != null ? fixedLocation : "line " + line + ":" + column;
        }

        boolean is(Type expected) {
            return type == expected;
        }

        boolean isIdent(String word) {
            return type == Type.IDENT && text.equals(word);
        }

        /** How an error message quotes this token. */
        String quoted() {
            return switch (type) {
                case EOF -> "the end of the input";
                case STRING -> "string \"" + abbreviate(text) + "\"";
                default -> "'" + abbreviate(text) + "'";
            };
        }

        private static String abbreviate(String text) {
            return text.length() <= 40 ? text : text.substring(0, 37) + "...";
        }
    }

    private final String text;
    private final String fixedLocation;
    private final List<Token> lookahead = new ArrayList<>(2);
    private int pos;
    private int line = 1;
    private int column = 1;

    /** Tokenizes a whole file; tokens carry their line and column. */
    VrmlTokenizer(String text) {
        this(text, null);
    }

    /** Tokenizes a fragment (an attribute value); every token reports {@code location}. */
    VrmlTokenizer(String text, String location) {
        this.text = text;
        this.fixedLocation = location;
    }

    Token peek() throws ModelException {
        return peek(0);
    }

    /** The token {@code ahead} positions after the next one ({@code 0} is the next one). */
    Token peek(int ahead) throws ModelException {
        while (lookahead.size() <= ahead) {
            scan();
        }
        return lookahead.get(ahead);
    }

    Token next() throws ModelException {
        peek(0);
        return lookahead.remove(0);
    }

    /** Puts {@code tokens} before the next one, to be read next: a prototype's body in its instance's place. */
    void insert(List<Token> tokens) {
        lookahead.addAll(0, tokens);
    }

    /** The current location, for messages about the end of the input. */
    String location() {
        return fixedLocation != null ? fixedLocation : "line " + line + ":" + column;
    }

    /** Appends the next token (or, for "Node.field", three tokens) to the lookahead. */
    private void scan() throws ModelException {
        skipSpaceAndComments();
        int startLine = line;
        int startColumn = column;
        if (pos >= text.length()) {
            lookahead.add(token(Type.EOF, "", startLine, startColumn));
            return;
        }
        char c = text.charAt(pos);
        switch (c) {
            case '{' -> single(Type.OPEN_BRACE, "{");
            case '}' -> single(Type.CLOSE_BRACE, "}");
            case '[' -> single(Type.OPEN_BRACKET, "[");
            case ']' -> single(Type.CLOSE_BRACKET, "]");
            case '"' -> lookahead.add(string(startLine, startColumn));
            default -> word(startLine, startColumn);
        }
    }

    private Token token(Type type, String value, int tokenLine, int tokenColumn) {
        return new Token(type, value, tokenLine, tokenColumn, fixedLocation);
    }

    private void single(Type type, String value) {
        lookahead.add(token(type, value, line, column));
        advance();
    }

    private Token string(int startLine, int startColumn) throws ModelException {
        String where = fixedLocation != null ? fixedLocation
                : "line " + startLine + ":" + startColumn;
        advance();
        StringBuilder value = new StringBuilder();
        while (pos < text.length()) {
            char c = text.charAt(pos);
            if (c == '"') {
                advance();
                return token(Type.STRING, value.toString(), startLine, startColumn);
            }
            if (c == '\\' && pos + 1 < text.length()) {
                advance();
                c = text.charAt(pos);
            }
            value.append(c);
            advance();
        }
        throw new ModelException(Kind.MALFORMED, where + ": string never closed (missing \")");
    }

    private void word(int startLine, int startColumn) {
        int start = pos;
        while (pos < text.length() && !isDelimiter(text.charAt(pos))) {
            pos++;
        }
        column += pos - start;
        String word = text.substring(start, pos);
        if (isNumber(word)) {
            lookahead.add(token(Type.NUMBER, word, startLine, startColumn));
            return;
        }
        int dot = word.indexOf('.');
        if (dot > 0 && dot < word.length() - 1 && isIdentifier(word.substring(0, dot))
                && isIdentifier(word.substring(dot + 1))) {
            // "Node.field" in a ROUTE.
            lookahead.add(token(Type.IDENT, word.substring(0, dot), startLine, startColumn));
            lookahead.add(token(Type.PERIOD, ".", startLine, startColumn + dot));
            lookahead.add(token(Type.IDENT, word.substring(dot + 1), startLine,
                    startColumn + dot + 1));
            return;
        }
        lookahead.add(token(isIdentifier(word) ? Type.IDENT : Type.INVALID, word, startLine,
                startColumn));
    }

    /**
     * VRML97 numbers: an optional sign, then digits with an optional fraction and exponent, or
     * a hexadecimal integer ({@code 0x1F}). No NaN, no Infinity, no suffixes.
     */
    static boolean isNumber(String word) {
        int i = 0;
        int n = word.length();
        if (i < n && (word.charAt(i) == '+' || word.charAt(i) == '-')) {
            i++;
        }
        if (i + 1 < n && word.charAt(i) == '0'
                && (word.charAt(i + 1) == 'x' || word.charAt(i + 1) == 'X')) {
            int digits = 0;
            for (i += 2; i < n; i++, digits++) {
                if (Character.digit(word.charAt(i), 16) < 0) {
                    return false;
                }
            }
            return digits > 0;
        }
        int mantissa = 0;
        while (i < n && isDigit(word.charAt(i))) {
            i++;
            mantissa++;
        }
        if (i < n && word.charAt(i) == '.') {
            i++;
            while (i < n && isDigit(word.charAt(i))) {
                i++;
                mantissa++;
            }
        }
        if (mantissa == 0) {
            return false;
        }
        if (i < n && (word.charAt(i) == 'e' || word.charAt(i) == 'E')) {
            i++;
            if (i < n && (word.charAt(i) == '+' || word.charAt(i) == '-')) {
                i++;
            }
            int exponent = 0;
            while (i < n && isDigit(word.charAt(i))) {
                i++;
                exponent++;
            }
            if (exponent == 0) {
                return false;
            }
        }
        return i == n;
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /**
     * VRML97 identifiers: no leading digit, sign or period, and none of the characters the
     * grammar reserves.
     */
    static boolean isIdentifier(String word) {
        if (word.isEmpty()) {
            return false;
        }
        char first = word.charAt(0);
        if (Character.isDigit(first) || first == '+' || first == '-') {
            return false;
        }
        for (int i = 0; i < word.length(); i++) {
            char c = word.charAt(i);
            if (c == '.' || c == '\'' || c == '\\' || c < 0x21 || c == 0x7f) {
                return false;
            }
        }
        return true;
    }

    private static boolean isDelimiter(char c) {
        return c <= ' ' || c == ',' || c == '{' || c == '}' || c == '[' || c == ']' || c == '"'
                || c == '#';
    }

    private void skipSpaceAndComments() {
        while (pos < text.length()) {
            char c = text.charAt(pos);
            if (c == '#') {
                while (pos < text.length() && text.charAt(pos) != '\n') {
                    advance();
                }
            } else if (c <= ' ' || c == ',') {
                advance();
            } else {
                return;
            }
        }
    }

    private void advance() {
        if (text.charAt(pos) == '\n') {
            line++;
            column = 1;
        } else {
            column++;
        }
        pos++;
    }
}
