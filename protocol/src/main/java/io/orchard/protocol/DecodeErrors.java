package io.orchard.protocol;

import com.fasterxml.jackson.annotation.JsonFormat;
import com.fasterxml.jackson.annotation.JsonValue;
import io.orchard.protocol.message.ErrorCode;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.StringJoiner;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.core.TokenStreamContext;
import tools.jackson.core.exc.InputCoercionException;
import tools.jackson.core.exc.StreamConstraintsException;
import tools.jackson.core.exc.StreamReadException;
import tools.jackson.databind.exc.InvalidTypeIdException;
import tools.jackson.databind.exc.MismatchedInputException;
import tools.jackson.databind.exc.ValueInstantiationException;

/**
 * What the reader refused, told in the protocol's words: the field as a path ({@code from.x},
 * {@code objects[0].at.bearing}), the bad value as the line has it, and what was expected. The
 * reader's own messages name its classes and switches; none of that reaches a client, so every
 * text here is built from this class's phrases and pieces of the line alone.
 */
final class DecodeErrors {

    private static final Pattern QUOTED = Pattern.compile("'([^']*)'");
    private static final Pattern MISSING = Pattern.compile("^missing field '([^']*)'$");
    private static final Pattern UNEXPECTED = Pattern.compile("^Unexpected character \\('(.)' \\(code (\\d+)\\)\\)");
    private static final Pattern LIMIT = Pattern.compile("\\((\\d+)\\) exceeds the maximum allowed \\((\\d+)");
    private static final int SHOWN = 40;

    private DecodeErrors() {}

    /** The refusal of a line, as the server sends it back. */
    static ProtocolException translate(JacksonException e) {
        String path = path(e.getPath());
        String original = firstLine(e.getOriginalMessage());
        JsonParser parser = e.processor() instanceof JsonParser p ? p : null;
        if (e instanceof InvalidTypeIdException typeId) {
            String id = typeId.getTypeId();
            if (id == null || id.isEmpty()) {
                return new ProtocolException(ErrorCode.MISSING_FIELD, "missing field 'type'");
            }
            return new ProtocolException(ErrorCode.UNKNOWN_TYPE,
                    "unknown message type " + shown(id) + "; known types are " + MessageTypes.names());
        }
        if (e instanceof ValueInstantiationException) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            String problem = firstLine(cause.getMessage());
            Matcher missing = MISSING.matcher(problem);
            if (missing.matches()) {
                return new ProtocolException(ErrorCode.MISSING_FIELD,
                        "missing field '" + join(path, missing.group(1)) + "'");
            }
            if (!(cause instanceof IllegalArgumentException)) {
                return new ProtocolException(ErrorCode.INVALID_VALUE, (path.isEmpty() ? "the message" : path)
                        + " has an invalid value");
            }
            return new ProtocolException(ErrorCode.INVALID_VALUE, path.isEmpty() ? problem : path + "." + problem);
        }
        if (original.startsWith("Missing required creator property")) {
            Matcher name = QUOTED.matcher(original.replace('`', '\''));
            String field = name.find() ? name.group(1) : "?";
            String full = path.equals(field) || path.endsWith("." + field) ? path : join(path, field);
            return new ProtocolException(ErrorCode.MISSING_FIELD, "missing field '" + full + "'");
        }
        if (original.startsWith("Trailing token")) {
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "malformed JSON: more than one JSON value on the line");
        }
        if (e instanceof StreamConstraintsException) {
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "malformed JSON: " + limit(original));
        }
        if (e instanceof InputCoercionException coercion && parser != null) {
            String field = path.isEmpty() ? String.valueOf(parser.currentName()) : path;
            return new ProtocolException(ErrorCode.INVALID_VALUE, field + " must be " + range(coercion.getTargetType())
                    + ", was " + shorten(text(parser)));
        }
        if (e instanceof StreamReadException && !(e instanceof MismatchedInputException)) {
            return malformed(e, original, parser);
        }
        if (path.isEmpty()) {
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "a line must hold one JSON object");
        }
        if (e instanceof MismatchedInputException mismatch && parser != null) {
            return new ProtocolException(ErrorCode.INVALID_VALUE,
                    path + " must be " + expected(mismatch.getTargetType(), parser.currentToken()) + ", was "
                            + actual(parser));
        }
        return new ProtocolException(ErrorCode.INVALID_VALUE, path + " has a value of the wrong kind");
    }

    /** A line that is not well-formed JSON: where, near which field, and what is wrong there. */
    private static ProtocolException malformed(JacksonException e, String original, JsonParser parser) {
        String where = e.getLocation() == null || e.getLocation().getColumnNr() < 1 ? ""
                : " at column " + e.getLocation().getColumnNr();
        String field = parser == null ? "" : contextPath(parser.streamReadContext());
        if (original.startsWith("Non-standard token")) {
            Matcher token = QUOTED.matcher(original);
            String literal = token.find() ? token.group(1) : "NaN";
            // Not JSON, so malformed; but the client wants to know which number it failed to write.
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "malformed JSON" + where + ": "
                    + (field.isEmpty() ? "a number" : field) + " must be a finite number, was " + literal
                    + " (not JSON)");
        }
        return new ProtocolException(ErrorCode.MALFORMED_JSON, "malformed JSON" + where
                + (field.isEmpty() ? "" : " near " + field) + ": " + describe(original));
    }

    /** What is wrong with the JSON, from the reader's message, in this document's words. */
    private static String describe(String original) {
        if (original.startsWith("Unexpected end-of-input")) {
            return original.contains("closing quote") ? "the line ends inside a string"
                    : "the line ends before the JSON object is complete";
        }
        if (original.startsWith("Duplicate Object property")) {
            int open = original.indexOf('"');
            int close = original.lastIndexOf('"');
            return "duplicate key" + (open >= 0 && close > open ? " " + shown(original.substring(open + 1, close)) : "");
        }
        if (original.contains("Leading zeroes not allowed")) {
            return "a number must not start with a 0 followed by more digits";
        }
        if (original.startsWith("Illegal unquoted character")) {
            Matcher code = Pattern.compile("code (\\d+)").matcher(original);
            return "a control character" + (code.find() ? " (" + codePoint(Integer.parseInt(code.group(1))) + ")" : "")
                    + " must be escaped in a string";
        }
        if (original.startsWith("Unrecognized character escape")) {
            Matcher escape = QUOTED.matcher(original);
            return (escape.find() ? "'\\" + escape.group(1) + "'" : "this") + " is not a JSON escape";
        }
        if (original.startsWith("Unrecognized token")) {
            Matcher token = QUOTED.matcher(original);
            return "unexpected " + (token.find() ? shown(token.group(1)) : "text")
                    + ", expected a value (a string, a number, an object, an array, true, false or null)";
        }
        if (original.startsWith("Unexpected close marker")) {
            Matcher marker = QUOTED.matcher(original);
            return "unexpected " + (marker.find() ? "'" + marker.group(1) + "'" : "close")
                    + " with no object or array open";
        }
        Matcher unexpected = UNEXPECTED.matcher(original);
        if (unexpected.find()) {
            String character = character(Integer.parseInt(unexpected.group(2)));
            if (original.contains("comment")) {
                return "comments are not JSON";
            }
            if (original.contains("hexadecimal")) {
                return "hexadecimal numbers are not JSON";
            }
            if (original.contains("hex-digit")) {
                return "a \\u escape needs four hexadecimal digits, found " + character;
            }
            if (original.contains("in numeric value")) {
                return "a malformed number: unexpected " + character;
            }
            if (original.contains("double-quote to start property name")) {
                return "unexpected " + character + ", expected a key in double quotes";
            }
            if (original.contains("separate Object entries")) {
                return "unexpected " + character + ", expected ',' or '}'";
            }
            if (original.contains("separate Array entries")) {
                return "unexpected " + character + ", expected ',' or ']'";
            }
            if (original.contains("colon")) {
                return "unexpected " + character + ", expected ':'";
            }
            if (original.contains("value")) {
                return "unexpected " + character + ", expected a value";
            }
            return "unexpected " + character;
        }
        if (original.startsWith("Invalid numeric value")) {
            return "a malformed number";
        }
        return "not well-formed here";
    }

    /** A read limit the line went beyond, named by what it limits. */
    private static String limit(String original) {
        Matcher numbers = LIMIT.matcher(original);
        String over = numbers.find() ? " (" + numbers.group(1) + ", at most " + numbers.group(2) + ")" : "";
        String lower = original.toLowerCase(Locale.ROOT);
        if (lower.contains("nesting depth")) {
            return "objects and arrays nest too deep" + over;
        }
        if (lower.contains("number value length")) {
            return "a number has too many characters" + over;
        }
        if (lower.contains("string value length")) {
            return "a string is too long" + over;
        }
        if (lower.contains("name length")) {
            return "a key is too long" + over;
        }
        return "the line is beyond what the server reads" + over;
    }

    /** What an integer field holds, for a number out of its range. */
    private static String range(Class<?> target) {
        if (target == int.class || target == Integer.class) {
            return "an integer from " + Integer.MIN_VALUE + " to " + Integer.MAX_VALUE;
        }
        return "an integer from " + Long.MIN_VALUE + " to " + Long.MAX_VALUE;
    }

    /** What a field of this Java type holds on the wire. */
    private static String expected(Class<?> target, JsonToken found) {
        if (target == null) {
            return "another kind of value";
        }
        if (target == long.class || target == Long.class || target == int.class || target == Integer.class) {
            return found == JsonToken.VALUE_NUMBER_FLOAT ? "an integer, without fraction or exponent" : "an integer";
        }
        if (target == double.class || target == Double.class || target == float.class || target == Float.class) {
            return "a number";
        }
        if (target == boolean.class || target == Boolean.class) {
            return "true or false";
        }
        if (target == String.class) {
            return "a string";
        }
        if (target.isEnum()) {
            StringJoiner names = new StringJoiner(", ", "one of ", "");
            for (Object constant : target.getEnumConstants()) {
                names.add("'" + wireName((Enum<?>) constant) + "'");
            }
            return names.toString();
        }
        if (Collection.class.isAssignableFrom(target) || target.isArray()) {
            return "an array";
        }
        return "an object";
    }

    /** The value the parser stands on, as the line has it. */
    private static String actual(JsonParser parser) {
        JsonToken token = parser.currentToken();
        if (token == null) {
            return "nothing";
        }
        return switch (token) {
            case START_OBJECT -> "an object";
            case START_ARRAY -> "an array";
            case VALUE_STRING -> "the string " + shown(text(parser));
            case VALUE_NULL -> "null";
            default -> shorten(text(parser));
        };
    }

    private static String text(JsonParser parser) {
        try {
            return parser.getString();
        } catch (JacksonException unreadable) {
            return "?";
        }
    }

    /** The name of an enum constant on the wire: what its {@link JsonValue} method returns. */
    private static String wireName(Enum<?> constant) {
        for (Method method : constant.getDeclaringClass().getMethods()) {
            if (method.isAnnotationPresent(JsonValue.class) && method.getParameterCount() == 0) {
                try {
                    return String.valueOf(method.invoke(constant));
                } catch (IllegalAccessException | InvocationTargetException e) {
                    return constant.name();
                }
            }
        }
        return constant.name();
    }

    /** A field path from where the reader stands in the line: {@code from.x}, {@code objects[0].at}. */
    private static String contextPath(TokenStreamContext context) {
        Deque<String> parts = new ArrayDeque<>();
        for (TokenStreamContext at = context; at != null && !at.inRoot(); at = at.getParent()) {
            if (at.inArray()) {
                parts.addFirst("[" + Math.max(0, at.getCurrentIndex()) + "]");
            } else if (at.inObject() && at.currentName() != null) {
                parts.addFirst("." + shorten(at.currentName()));
            }
        }
        String joined = String.join("", parts);
        return joined.startsWith(".") ? joined.substring(1) : joined;
    }

    static String path(List<JacksonException.Reference> references) {
        StringBuilder path = new StringBuilder();
        for (JacksonException.Reference reference : references) {
            if (reference.getPropertyName() != null && writtenAsArray(reference.from())) {
                continue; // the element's index follows, and the check's text names the component
            }
            if (reference.getPropertyName() != null) {
                if (path.length() > 0) {
                    path.append('.');
                }
                path.append(reference.getPropertyName());
            } else if (reference.getIndex() >= 0) {
                path.append('[').append(reference.getIndex()).append(']');
            }
        }
        return path.toString();
    }

    /** Whether the value is a record written as an array of its components (a tuple of the lean form). */
    private static boolean writtenAsArray(Object from) {
        Class<?> type = from instanceof Class<?> c ? c : from == null ? null : from.getClass();
        JsonFormat format = type == null ? null : type.getAnnotation(JsonFormat.class);
        return format != null && format.shape() == JsonFormat.Shape.ARRAY;
    }

    private static String join(String path, String field) {
        return path.isEmpty() ? field : path + "." + field;
    }

    /** A character of the line: itself when printable ASCII, otherwise its code point. */
    private static String character(int code) {
        if (code == '\'') {
            return "a single quote";
        }
        return code > 0x20 && code < 0x7f ? "'" + (char) code + "'" : codePoint(code);
    }

    private static String codePoint(int code) {
        return String.format(Locale.ROOT, "U+%04X", code);
    }

    /** A piece of the line in quotes, cut short when long. */
    static String shown(String value) {
        return "'" + shorten(value) + "'";
    }

    private static String shorten(String value) {
        return value.length() > SHOWN ? value.substring(0, SHOWN) + "..." : value;
    }

    private static String firstLine(String text) {
        if (text == null) {
            return "";
        }
        int newline = text.indexOf('\n');
        String line = newline < 0 ? text : text.substring(0, newline);
        return line.strip();
    }
}
