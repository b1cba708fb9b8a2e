package io.orchard.viewer.replay;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One line of a recording, split into its top-level fields without decoding the message:
 * {@code {"tick":12,"time":0.6,"dir":"out","to":"viewers","msg":{...}}}. String fields keep their
 * unescaped text, numbers their literal, and objects their raw JSON, so that only the lines a
 * viewer needs are decoded.
 */
final class RecordLine {

    private final Map<String, String> fields;

    private RecordLine(Map<String, String> fields) {
        this.fields = fields;
    }

    /**
     * Splits a line. A line in the server's own layout, with {@code "msg"} last, has only its short
     * head scanned, so that the long perceptions a viewer skips cost next to nothing; any other
     * layout is scanned whole.
     *
     * @throws IllegalArgumentException naming the position when the line is not a JSON object
     */
    static RecordLine parse(String line) {
        int msg = line.indexOf(MSG);
        int end = line.lastIndexOf('}');
        if (line.startsWith("{\"tick\":") && msg > 0 && end > msg + MSG.length()) {
            try {
                RecordLine head = scan(line.substring(0, msg) + "}");
                if (!head.fields.containsKey("msg")) {
                    head.fields.put("msg", line.substring(msg + MSG.length(), end).strip());
                    return head;
                }
            } catch (IllegalArgumentException e) {
                // not the server's layout after all: scan the whole line below
            }
        }
        return scan(line);
    }

    private static final String MSG = ",\"msg\":";

    private static RecordLine scan(String line) {
        Scanner scanner = new Scanner(line);
        Map<String, String> fields = new LinkedHashMap<>();
        scanner.skipSpace();
        scanner.expect('{');
        scanner.skipSpace();
        if (scanner.peek() == '}') {
            return new RecordLine(fields);
        }
        while (true) {
            scanner.skipSpace();
            String key = scanner.string();
            scanner.skipSpace();
            scanner.expect(':');
            scanner.skipSpace();
            fields.put(key, scanner.value());
            scanner.skipSpace();
            char c = scanner.next();
            if (c == '}') {
                break;
            }
            if (c != ',') {
                throw scanner.error("expected ',' or '}' but found '" + c + "'");
            }
        }
        return new RecordLine(fields);
    }

    /** A field's value: a string's text, a number's literal, or an object's raw JSON; null when absent. */
    String get(String name) {
        return fields.get(name);
    }

    /** A numeric field, or {@code fallback} when absent or not a number. */
    double number(String name, double fallback) {
        String text = fields.get(name);
        if (text == null) {
            return fallback;
        }
        try {
            return Double.parseDouble(text);
        } catch (NumberFormatException e) {
            return fallback;
        }
    }

    /** The message's {@code type}, read from the start of its raw JSON without decoding it; null if not found. */
    String messageType() {
        String msg = fields.get("msg");
        if (msg == null) {
            return null;
        }
        int key = msg.indexOf("\"type\"");
        if (key < 0) {
            return null;
        }
        int open = msg.indexOf('"', msg.indexOf(':', key) + 1);
        int close = open < 0 ? -1 : msg.indexOf('"', open + 1);
        return close < 0 ? null : msg.substring(open + 1, close);
    }

    /** A cursor over one line of JSON. */
    private static final class Scanner {

        private final String text;
        private int at;

        Scanner(String text) {
            this.text = text;
        }

        char peek() {
            if (at >= text.length()) {
                throw error("unexpected end of line");
            }
            return text.charAt(at);
        }

        char next() {
            char c = peek();
            at++;
            return c;
        }

        void expect(char wanted) {
            char c = next();
            if (c != wanted) {
                throw new IllegalArgumentException("expected '" + wanted + "' at column " + at + " but found '" + c + "'");
            }
        }

        void skipSpace() {
            while (at < text.length() && Character.isWhitespace(text.charAt(at))) {
                at++;
            }
        }

        String string() {
            expect('"');
            StringBuilder out = new StringBuilder();
            while (true) {
                char c = next();
                if (c == '"') {
                    return out.toString();
                }
                if (c == '\\') {
                    char escaped = next();
                    switch (escaped) {
                        case 'n' -> out.append('\n');
                        case 't' -> out.append('\t');
                        case 'r' -> out.append('\r');
                        case 'b' -> out.append('\b');
                        case 'f' -> out.append('\f');
                        case 'u' -> {
                            if (at + 4 > text.length()) {
                                throw error("truncated \\u escape");
                            }
                            out.append((char) Integer.parseInt(text.substring(at, at + 4), 16));
                            at += 4;
                        }
                        default -> out.append(escaped);
                    }
                } else {
                    out.append(c);
                }
            }
        }

        String value() {
            char c = peek();
            if (c == '"') {
                return string();
            }
            if (c == '{' || c == '[') {
                int start = at;
                skipNested();
                return text.substring(start, at);
            }
            int start = at;
            while (at < text.length() && ",}] \t".indexOf(text.charAt(at)) < 0) {
                at++;
            }
            if (start == at) {
                throw error("expected a value");
            }
            return text.substring(start, at);
        }

        private void skipNested() {
            int depth = 0;
            do {
                char c = next();
                if (c == '"') {
                    at--;
                    string();
                } else if (c == '{' || c == '[') {
                    depth++;
                } else if (c == '}' || c == ']') {
                    depth--;
                }
            } while (depth > 0);
        }

        IllegalArgumentException error(String what) {
            return new IllegalArgumentException(what + " at column " + (at + 1));
        }
    }
}
