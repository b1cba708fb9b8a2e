package io.orchard.protocol.value;

import java.util.List;
import java.util.regex.Pattern;

/**
 * The validation every protocol record runs in its constructor, so that a value that exists is a
 * valid one, whether it was built in Java or decoded from a line. Each check names the field and
 * the bad value, because that text travels back to the client in an {@code ErrorMessage}.
 *
 * <p>Public only because the records of {@code io.orchard.protocol.message} use it too.
 */
public final class Checks {

    /** Agent, joint and time-sensor names: a letter, then letters, digits, '_' or '-'; at most 32. */
    public static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_-]{0,31}");

    /**
     * Joint and time-sensor names, as the tools that make models write them: 1 to 64 characters, the first a
     * letter, a digit or '_', then letters, digits, spaces and '_', '-', '.', ':', '|' or '#', not ending in a space
     * (such as {@code Shoulder.L_CatArmature}, {@code mixamorig:Hips}, {@code Armature|Walk} or {@code clip#0}).
     */
    public static final Pattern PART_NAME = Pattern.compile("[A-Za-z0-9_](?:[A-Za-z0-9_ .:|#-]{0,62}[A-Za-z0-9_.:|#-])?");

    /** The longest free text (an instruction, something an agent says, a reason) in characters. */
    public static final int MAX_TEXT = 1000;

    private Checks() {}

    /** {@code value} if it is not null; otherwise an exception says the field is missing. */
    public static <T> T present(T value, String field) {
        if (value == null) {
            throw new IllegalArgumentException("missing field '" + field + "'");
        }
        return value;
    }

    /** {@code value} if it is a finite number (not NaN, not infinite). */
    public static double finite(double value, String field) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(field + " must be a finite number, was " + value);
        }
        return value;
    }

    /** {@code value} if it is finite and greater than 0. */
    public static double positive(double value, String field) {
        finite(value, field);
        if (value <= 0) {
            throw new IllegalArgumentException(field + " must be greater than 0, was " + value);
        }
        return value;
    }

    /** {@code value} if it is finite and 0 or more. */
    public static double nonNegative(double value, String field) {
        finite(value, field);
        if (value < 0) {
            throw new IllegalArgumentException(field + " must not be negative, was " + value);
        }
        return value;
    }

    /** {@code value} if it is 0 or more. */
    public static long nonNegative(long value, String field) {
        if (value < 0) {
            throw new IllegalArgumentException(field + " must not be negative, was " + value);
        }
        return value;
    }

    /** {@code value} if it is present and matches {@link #NAME}. */
    public static String name(String value, String field) {
        present(value, field);
        if (!isName(value)) {
            throw new IllegalArgumentException(field + " must be a letter followed by up to 31 letters, digits,"
                    + " '_' or '-', was " + quote(value));
        }
        return value;
    }

    /** {@code value} if it is present and matches {@link #PART_NAME}: the name of a joint or time sensor in a model. */
    public static String partName(String value, String field) {
        present(value, field);
        if (!PART_NAME.matcher(value).matches()) {
            throw new IllegalArgumentException(field + " must be 1 to 64 characters, a letter, digit or '_' followed by"
                    + " letters, digits, spaces, '_', '-', '.', ':', '|' or '#', not ending in a space, was "
                    + quote(value));
        }
        return value;
    }

    /** Whether {@code value} matches {@link #NAME}; checked by hand because it runs for every perceived agent. */
    static boolean isName(String value) {
        int length = value.length();
        if (length == 0 || length > 32 || !isAsciiLetter(value.charAt(0))) {
            return false;
        }
        for (int i = 1; i < length; i++) {
            char c = value.charAt(i);
            if (!isAsciiLetter(c) && !(c >= '0' && c <= '9') && c != '_' && c != '-') {
                return false;
            }
        }
        return true;
    }

    private static boolean isAsciiLetter(char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    }

    /** An object id such as a fruit's or a tree's: non-blank, printable, at most 64 characters. */
    public static String id(String value, String field) {
        present(value, field);
        if (!isPrintableId(value)) {
            throw new IllegalArgumentException(field + " must be 1 to 64 printable characters, was " + quote(value));
        }
        return value;
    }

    /** {@code value} if it is present and at most {@link #MAX_TEXT} characters long. */
    public static String text(String value, String field) {
        present(value, field);
        if (value.length() > MAX_TEXT) {
            throw new IllegalArgumentException(field + " must be at most " + MAX_TEXT + " characters, was "
                    + value.length());
        }
        return value;
    }

    /** An optional text: null stays null, anything else is checked as {@link #text}. */
    public static String optionalText(String value, String field) {
        return value == null ? null : text(value, field);
    }

    /**
     * {@code value}, copied, if it is present and holds no null; otherwise an exception names the field and the
     * null's index.
     */
    public static <T> List<T> list(List<T> value, String field) {
        present(value, field);
        for (int i = 0; i < value.size(); i++) {
            if (value.get(i) == null) {
                throw new IllegalArgumentException(field + "[" + i + "] must not be null");
            }
        }
        return List.copyOf(value);
    }

    /** Not blank, at most 64 characters, none a control character: in one pass, as it runs for every perceived thing. */
    private static boolean isPrintableId(String value) {
        int length = value.length();
        if (length == 0 || length > 64) {
            return false;
        }
        boolean visible = false;
        for (int i = 0; i < length; i++) {
            char c = value.charAt(i);
            if (Character.isISOControl(c)) {
                return false;
            }
            visible |= !Character.isWhitespace(c);
        }
        return visible;
    }

    static String quote(String value) {
        String shown = value.length() > 40 ? value.substring(0, 40) + "..." : value;
        return "'" + shown + "'";
    }
}
