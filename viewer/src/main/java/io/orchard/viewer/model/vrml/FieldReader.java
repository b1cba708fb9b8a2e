package io.orchard.viewer.model.vrml;

import io.orchard.viewer.model.FieldDef;
import io.orchard.viewer.model.FieldType;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ParseBudget;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Token;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Type;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Reads typed field values (everything but node fields) from VRML97 tokens or from X3D attribute
 * text, into the representations {@link FieldType} lists. Every number is checked (finite, in
 * range, an integer where one is required) and counted against the array-value limit as it is
 * read.
 */
public final class FieldReader {

    private final ParseBudget budget;

    /** A reader that counts every number it reads against {@code budget}. */
    public FieldReader(ParseBudget budget) {
        this.budget = budget;
    }

    /** Reads a VRML97 field value: one value, or a bracketed list for MF types. */
    Object readVrml(VrmlTokenizer tokens, FieldDef def, SceneNode node) throws ModelException {
        FieldType type = def.type();
        if (type == FieldType.SFBOOL) {
            return bool(tokens.next(), def, node);
        }
        if (type == FieldType.SFSTRING) {
            return string(tokens.next(), def, node);
        }
        if (type == FieldType.MFSTRING) {
            if (!tokens.peek().is(Type.OPEN_BRACKET)) {
                return List.of(string(tokens.next(), def, node));
            }
            tokens.next();
            List<String> values = new ArrayList<>();
            while (!tokens.peek().is(Type.CLOSE_BRACKET)) {
                values.add(string(tokens.next(), def, node));
            }
            tokens.next();
            return List.copyOf(values);
        }
        if (!type.isMultiple()) {
            return numbers(tokens, def, node, type.components(), End.AFTER_COUNT);
        }
        if (!tokens.peek().is(Type.OPEN_BRACKET)) {
            return numbers(tokens, def, node, type.components(), End.AFTER_COUNT);
        }
        tokens.next();
        return numbers(tokens, def, node, Integer.MAX_VALUE, End.AT_BRACKET);
    }

    /** Reads an X3D attribute value: the whole text is the value. */
    public Object readAttribute(String text, FieldDef def, SceneNode node, String location)
            throws ModelException {
        FieldType type = def.type();
        switch (type) {
            case SFSTRING -> {
                return text;
            }
            case SFBOOL -> {
                return bool(new Token(Type.IDENT, text.strip(), location), def, node);
            }
            case MFSTRING -> {
                if (text.indexOf('"') < 0) {
                    return text.isBlank() ? List.of() : List.of(text.strip());
                }
                VrmlTokenizer tokens = new VrmlTokenizer(text, location);
                List<String> values = new ArrayList<>();
                while (!tokens.peek().is(Type.EOF)) {
                    values.add(string(tokens.next(), def, node));
                }
                return List.copyOf(values);
            }
            default -> {
                VrmlTokenizer tokens = new VrmlTokenizer(text, location);
                int count = type.isMultiple() ? Integer.MAX_VALUE : type.components();
                Object value = numbers(tokens, def, node, count,
                        type.isMultiple() ? End.AT_END : End.AFTER_COUNT);
                Token rest = tokens.next();
                if (!rest.is(Type.EOF)) {
                    throw error(Kind.MALFORMED, rest, def, node, "expected " + type.components()
                            + " number" + (type.components() == 1 ? "" : "s") + " (" + type
                            + ") but found more: " + rest.quoted());
                }
                return value;
            }
        }
    }

    /** How a run of numbers ends. */
    private enum End { AFTER_COUNT, AT_BRACKET, AT_END }

    /**
     * Reads numbers: exactly {@code count} of them, up to a closing bracket, or up to the end of
     * an attribute.
     */
    private Object numbers(VrmlTokenizer tokens, FieldDef def, SceneNode node, int count,
                           End end) throws ModelException {
        FieldType type = def.type();
        if (type.isScalar()) {
            return number(tokens.next(), def, node);
        }
        boolean integers = type.isInteger();
        boolean counted = type.isMultiple();
        float[] floats = integers ? null : new float[Math.min(count, 16)];
        int[] ints = integers ? new int[Math.min(count, 16)] : null;
        int n = 0;
        while (n < count) {
            Token token = tokens.peek();
            if (end == End.AT_BRACKET && token.is(Type.CLOSE_BRACKET)) {
                tokens.next();
                break;
            }
            if (end == End.AT_END && token.is(Type.EOF)) {
                break;
            }
            if (end == End.AT_BRACKET && token.is(Type.EOF)) {
                throw error(Kind.MALFORMED, token, def, node, "list never closed (missing ])");
            }
            if (end == End.AFTER_COUNT && isStructural(token)) {
                throw error(Kind.MALFORMED, token, def, node, "a " + type + " needs "
                        + type.components() + " numbers but " + n + " were given");
            }
            tokens.next();
            if (counted) {
                budget.addValue(() -> token.location() + ": " + node.label() + " field "
                        + def.name());
            }
            if (integers) {
                if (n == ints.length) {
                    ints = Arrays.copyOf(ints, n * 2);
                }
                ints[n++] = integer(token, def, node);
            } else {
                if (n == floats.length) {
                    floats = Arrays.copyOf(floats, n * 2);
                }
                floats[n++] = (float) number(token, def, node);
            }
        }
        int components = Math.max(1, type.components());
        if (n % components != 0 || (!type.isMultiple() && n != components)) {
            throw error(Kind.MALFORMED, tokens.peek(), def, node, "a " + type + " needs "
                    + (type.isMultiple() ? "a multiple of " : "") + components
                    + " numbers but " + n + " were given");
        }
        if (integers) {
            return type.isMultiple() ? Arrays.copyOf(ints, n) : Integer.valueOf(ints[0]);
        }
        float[] result = Arrays.copyOf(floats, n);
        if (type == FieldType.SFCOLOR || type == FieldType.MFCOLOR) {
            for (int i = 0; i < n; i++) {
                result[i] = Math.max(0f, Math.min(1f, result[i]));
            }
        }
        return result;
    }

    /** A token that ends a value: a bracket, a brace or the end of the input. */
    private static boolean isStructural(Token token) {
        return switch (token.type()) {
            case OPEN_BRACE, CLOSE_BRACE, OPEN_BRACKET, CLOSE_BRACKET, EOF -> true;
            default -> false;
        };
    }

    private static double number(Token token, FieldDef def, SceneNode node)
            throws ModelException {
        if (!token.is(Type.NUMBER)) {
            throw error(token.is(Type.EOF) ? Kind.MALFORMED : Kind.BAD_VALUE, token, def, node,
                    "expected a number (" + def.type() + ") but found " + token.quoted());
        }
        String text = token.text();
        double value;
        if (isHex(text)) {
            value = integer(token, def, node);
        } else {
            value = Double.parseDouble(text);
        }
        boolean fitsFloat = def.type() == FieldType.SFTIME || Math.abs(value) <= Float.MAX_VALUE;
        if (!Double.isFinite(value) || !fitsFloat) {
            throw error(Kind.BAD_VALUE, token, def, node, "number " + token.quoted()
                    + " is out of range for " + def.type());
        }
        return value;
    }

    private static int integer(Token token, FieldDef def, SceneNode node) throws ModelException {
        String text = token.text();
        if (token.is(Type.NUMBER)) {
            try {
                if (isHex(text)) {
                    boolean negative = text.startsWith("-");
                    String digits = text.substring(text.indexOf('x') >= 0 ? text.indexOf('x') + 1
                            : text.indexOf('X') + 1);
                    long value = Long.parseLong(digits, 16);
                    if (value <= 0xFFFFFFFFL) {
                        return negative ? -(int) value : (int) value;
                    }
                } else if (text.indexOf('.') < 0 && text.indexOf('e') < 0
                        && text.indexOf('E') < 0) {
                    long value = Long.parseLong(text.startsWith("+") ? text.substring(1) : text);
                    if (value >= Integer.MIN_VALUE && value <= Integer.MAX_VALUE) {
                        return (int) value;
                    }
                }
            } catch (NumberFormatException tooLong) {
                // falls through to the error below
            }
            if (def.type().isInteger()) {
                throw error(Kind.BAD_VALUE, token, def, node, "expected an integer ("
                        + def.type() + ") but found " + token.quoted());
            }
            throw error(Kind.BAD_VALUE, token, def, node, "number " + token.quoted()
                    + " is out of range");
        }
        throw error(token.is(Type.EOF) ? Kind.MALFORMED : Kind.BAD_VALUE, token, def, node,
                "expected an integer (" + def.type() + ") but found " + token.quoted());
    }

    private static boolean isHex(String text) {
        return text.contains("x") || text.contains("X");
    }

    private static boolean bool(Token token, FieldDef def, SceneNode node) throws ModelException {
        String text = token.text();
        if (token.is(Type.IDENT)) {
            if (text.equals("TRUE") || text.equals("true")) {
                return true;
            }
            if (text.equals("FALSE") || text.equals("false")) {
                return false;
            }
        }
        throw error(token.is(Type.EOF) ? Kind.MALFORMED : Kind.BAD_VALUE, token, def, node,
                "expected TRUE or FALSE (SFBool) but found " + token.quoted());
    }

    private static String string(Token token, FieldDef def, SceneNode node)
            throws ModelException {
        if (!token.is(Type.STRING)) {
            throw error(token.is(Type.EOF) ? Kind.MALFORMED : Kind.BAD_VALUE, token, def, node,
                    "expected a quoted string (" + def.type() + ") but found " + token.quoted());
        }
        return token.text();
    }

    static ModelException error(Kind kind, Token token, FieldDef def, SceneNode node,
                                String problem) {
        return new ModelException(kind, token.location() + ": " + node.label() + " field "
                + def.name() + ": " + problem);
    }
}
