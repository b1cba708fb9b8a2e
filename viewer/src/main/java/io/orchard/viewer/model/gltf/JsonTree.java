package io.orchard.viewer.model.gltf;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A strict JSON reader (RFC 8259) with a nesting limit, producing maps, lists, strings,
 * doubles, booleans and nulls. It exists to inspect a glTF document before jME's loader sees
 * it: that loader's JSON library recurses without a bound, so a deeply nested document would
 * overflow its stack, and it would follow external URIs that must be refused first.
 */
final class JsonTree {

    private final String text;
    private final int maxDepth;
    private int pos;
    private int depth;

    private JsonTree(String text, int maxDepth) {
        this.text = text;
        this.maxDepth = maxDepth;
    }

    static Object parse(String text, int maxDepth) throws ModelException {
        JsonTree parser = new JsonTree(text, maxDepth);
        if (text.startsWith("\uFEFF")) {
            parser.pos = 1;
        }
        Object value = parser.value();
        parser.skipSpace();
        if (parser.pos != text.length()) {
            throw parser.error("unexpected " + parser.describe() + " after the document");
        }
        return value;
    }

    private Object value() throws ModelException {
        skipSpace();
        if (pos >= text.length()) {
            throw error("the document ends where a value belongs (truncated?)");
        }
        char c = text.charAt(pos);
        return switch (c) {
            case '{' -> object();
            case '[' -> array();
            case '"' -> string();
            case 't' -> literal("true", Boolean.TRUE);
            case 'f' -> literal("false", Boolean.FALSE);
            case 'n' -> literal("null", null);
            default -> {
                if (c == '-' || (c >= '0' && c <= '9')) {
                    yield number();
                }
                throw error("unexpected " + describe());
            }
        };
    }

    private Map<String, Object> object() throws ModelException {
        enter();
        pos++;
        Map<String, Object> members = new LinkedHashMap<>();
        skipSpace();
        if (peek() == '}') {
            pos++;
            depth--;
            return members;
        }
        while (true) {
            skipSpace();
            if (peek() != '"') {
                throw error("expected a member name in quotes but found " + describe());
            }
            String name = string();
            skipSpace();
            expect(':');
            members.put(name, value());
            skipSpace();
            char c = peek();
            pos++;
            if (c == '}') {
                depth--;
                return members;
            }
            if (c != ',') {
                pos--;
                throw error("expected ',' or '}' in an object but found " + describe());
            }
        }
    }

    private List<Object> array() throws ModelException {
        enter();
        pos++;
        List<Object> items = new ArrayList<>();
        skipSpace();
        if (peek() == ']') {
            pos++;
            depth--;
            return items;
        }
        while (true) {
            items.add(value());
            skipSpace();
            char c = peek();
            pos++;
            if (c == ']') {
                depth--;
                return items;
            }
            if (c != ',') {
                pos--;
                throw error("expected ',' or ']' in an array but found " + describe());
            }
        }
    }

    private void enter() throws ModelException {
        if (++depth > maxDepth) {
            throw new ModelException(Kind.TOO_LARGE, "glTF JSON at offset " + pos
                    + ": nesting deeper than " + maxDepth + " levels");
        }
    }

    private String string() throws ModelException {
        int start = pos;
        pos++;
        StringBuilder value = new StringBuilder();
        while (pos < text.length()) {
            char c = text.charAt(pos++);
            if (c == '"') {
                return value.toString();
            }
            if (c < 0x20) {
                throw error("control character in a string");
            }
            if (c != '\\') {
                value.append(c);
                continue;
            }
            if (pos >= text.length()) {
                break;
            }
            char e = text.charAt(pos++);
            switch (e) {
                case '"', '\\', '/' -> value.append(e);
                case 'b' -> value.append('\b');
                case 'f' -> value.append('\f');
                case 'n' -> value.append('\n');
                case 'r' -> value.append('\r');
                case 't' -> value.append('\t');
                case 'u' -> {
                    if (pos + 4 > text.length()) {
                        throw error("truncated \\u escape");
                    }
                    try {
                        value.append((char) Integer.parseInt(text.substring(pos, pos + 4), 16));
                    } catch (NumberFormatException bad) {
                        throw error("bad \\u escape '" + text.substring(pos, pos + 4) + "'");
                    }
                    pos += 4;
                }
                default -> throw error("bad escape '\\" + e + "'");
            }
        }
        pos = start;
        throw error("string never closed (truncated?)");
    }

    private Double number() throws ModelException {
        int start = pos;
        if (peek() == '-') {
            pos++;
        }
        if (peek() == '0') {
            pos++;
        } else if (!digits()) {
            throw error("malformed number");
        }
        if (peek() == '.') {
            pos++;
            if (!digits()) {
                throw error("malformed number");
            }
        }
        if (peek() == 'e' || peek() == 'E') {
            pos++;
            if (peek() == '+' || peek() == '-') {
                pos++;
            }
            if (!digits()) {
                throw error("malformed number");
            }
        }
        double value = Double.parseDouble(text.substring(start, pos));
        if (!Double.isFinite(value)) {
            pos = start;
            throw new ModelException(Kind.BAD_VALUE, "glTF JSON at offset " + start
                    + ": number out of range");
        }
        return value;
    }

    private boolean digits() {
        int start = pos;
        while (pos < text.length() && text.charAt(pos) >= '0' && text.charAt(pos) <= '9') {
            pos++;
        }
        return pos > start;
    }

    private Object literal(String word, Object value) throws ModelException {
        if (!text.startsWith(word, pos)) {
            throw error("unexpected " + describe());
        }
        pos += word.length();
        return value;
    }

    private void expect(char c) throws ModelException {
        if (peek() != c) {
            throw error("expected '" + c + "' but found " + describe());
        }
        pos++;
    }

    private char peek() {
        return pos < text.length() ? text.charAt(pos) : '\0';
    }

    private void skipSpace() {
        while (pos < text.length()) {
            char c = text.charAt(pos);
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
                return;
            }
            pos++;
        }
    }

    private String describe() {
        if (pos >= text.length()) {
            return "the end of the document";
        }
        return "'" + text.charAt(pos) + "'";
    }

    private ModelException error(String problem) {
        return new ModelException(Kind.MALFORMED, "glTF JSON at offset " + pos + ": " + problem);
    }
}
