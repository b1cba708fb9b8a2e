package io.orchard.viewer.model.vrml;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Token;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Type;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * VRML97 prototypes, expanded as X3D's are ({@code X3dProtos}): a {@code PROTO}'s interface and
 * body are kept as tokens; an instance becomes the tokens of the body's first node, each
 * {@code field IS name} in it replaced by the instance's value or the interface's default, its
 * DEF names the instance's own ({@code Knee} in an instance DEF'd {@code LeftLeg} is
 * {@code LeftLeg.Knee}), and the parser reads those tokens in the instance's place. An
 * {@code EXTERNPROTO}'s instances are not drawn: its prototype is in a file never fetched.
 */
final class VrmlProtos {

    private static final Logger LOG = LoggerFactory.getLogger(VrmlProtos.class);
    /** Deepest nesting of instances inside prototype bodies: beyond it, a prototype instantiates itself. */
    static final int MAX_NESTING = 16;
    /** The words a node's name follows. */
    private static final Set<String> NAMING = Set.of("DEF", "USE", "ROUTE", "TO");
    private static final Set<String> FIELD_KINDS = Set.of("field", "exposedField", "eventIn", "eventOut");

    private record Proto(String name, Map<String, List<Token>> defaults, List<Token> body, String location) {
    }

    private final Map<String, Proto> protos = new HashMap<>();
    private final Map<String, String> externs = new HashMap<>();
    private final Map<String, Integer> counts = new HashMap<>();
    private final Set<String> warned = new HashSet<>();
    private final int mostExpansions;
    private int expansions;

    VrmlProtos(int mostExpansions) {
        this.mostExpansions = mostExpansions;
    }

    /** Reads {@code PROTO name [ interface ] { body }}, the PROTO keyword next. */
    void declare(VrmlTokenizer tokens) throws ModelException {
        Token start = tokens.next();
        Token name = tokens.next();
        expect(tokens, Type.OPEN_BRACKET, "'[' after PROTO " + name.text());
        Map<String, List<Token>> defaults = new LinkedHashMap<>();
        while (!tokens.peek().is(Type.CLOSE_BRACKET)) {
            Token kind = tokens.next();
            if (!FIELD_KINDS.contains(kind.text())) {
                throw new ModelException(Kind.MALFORMED, kind.location() + ": PROTO " + name.text()
                        + ": expected field, exposedField, eventIn or eventOut but found " + kind.quoted());
            }
            tokens.next();
            Token field = tokens.next();
            if (kind.text().equals("field") || kind.text().equals("exposedField")) {
                defaults.put(field.text(), value(tokens));
            }
        }
        tokens.next();
        expect(tokens, Type.OPEN_BRACE, "'{' after PROTO " + name.text() + "'s interface");
        List<Token> body = new ArrayList<>();
        int depth = 1;
        while (true) {
            Token token = tokens.next();
            if (token.is(Type.EOF)) {
                throw new ModelException(Kind.MALFORMED, start.location() + ": PROTO " + name.text()
                        + " never closed (missing '}')");
            }
            depth += token.is(Type.OPEN_BRACE) ? 1 : token.is(Type.CLOSE_BRACE) ? -1 : 0;
            if (depth == 0) {
                break;
            }
            body.add(token);
        }
        protos.put(name.text(), new Proto(name.text(), defaults, body, start.location()));
    }

    /** Notes an EXTERNPROTO's name, whose instances are not drawn. */
    void extern(String name, String location) {
        externs.put(name, location);
    }

    boolean declares(String type) {
        return protos.containsKey(type);
    }

    /** Whether {@code type} is an EXTERNPROTO's; says so once per type. */
    boolean isExtern(String type, String where) {
        if (!externs.containsKey(type)) {
            return false;
        }
        if (warned.add("extern:" + type)) {
            LOG.warn("{}: {} is not drawn: its prototype is an EXTERNPROTO ({}), in a file never fetched", where,
                    type, externs.get(type));
        }
        return true;
    }

    /**
     * Reads an instance of a declared prototype, its type name just read and its '{' next, and
     * puts in its place the tokens of the node it stands for, for the parser to read next.
     */
    void expand(Token type, String def, VrmlTokenizer tokens) throws ModelException {
        if (++expansions > mostExpansions) {
            throw new ModelException(Kind.TOO_LARGE, type.location() + ": PROTO instances make more than "
                    + mostExpansions + " nodes (does a PROTO instantiate itself?)");
        }
        Proto proto = protos.get(type.text());
        expect(tokens, Type.OPEN_BRACE, "'{' after " + type.text());
        Map<String, List<Token>> values = new LinkedHashMap<>(proto.defaults());
        while (!tokens.peek().is(Type.CLOSE_BRACE)) {
            Token field = tokens.next();
            if (field.is(Type.EOF)) {
                throw new ModelException(Kind.MALFORMED, type.location() + ": " + type.text()
                        + " never closed (missing '}')");
            }
            values.put(field.text(), value(tokens));
        }
        tokens.next();
        int count = counts.merge(proto.name(), 1, Integer::sum);
        String scope = def != null ? def : proto.name() + "#" + count;
        List<Token> body = proto.body();
        int[] first = firstNode(body, type);
        Map<String, String> renamed = new HashMap<>();
        for (int i = 0; i + 1 < body.size(); i++) {
            if (body.get(i).isIdent("DEF")) {
                renamed.put(body.get(i + 1).text(), scope + "." + body.get(i + 1).text());
            }
        }
        List<Token> out = new ArrayList<>();
        if (def != null) {
            if (body.get(first[0]).isIdent("DEF")) {
                renamed.put(body.get(first[0] + 1).text(), def);
            } else {
                out.add(new Token(Type.IDENT, "DEF", type.location()));
                out.add(new Token(Type.IDENT, def, type.location()));
            }
        }
        for (int i = first[0]; i < first[1]; i++) {
            Token token = body.get(i);
            if (token.isIdent("IS") && i + 1 < first[1]) {
                List<Token> value = values.get(body.get(++i).text());
                if (value != null) {
                    out.addAll(value);
                } else {
                    // An event connected to the interface: nothing to set.
                    out.remove(out.size() - 1);
                }
            } else if (token.is(Type.IDENT) && renamed.containsKey(token.text()) && i > 0 && NAMING.stream()
                    .anyMatch(body.get(i - 1)::isIdent)) {
                out.add(new Token(Type.IDENT, renamed.get(token.text()), token.location()));
            } else {
                out.add(token);
            }
        }
        if (first[1] < body.size() && warned.add("rest:" + proto.name())) {
            LOG.warn("{}: PROTO {}: only its body's first node is drawn for an instance; the nodes and ROUTEs"
                    + " after it are not", proto.location(), proto.name());
        }
        tokens.insert(out);
    }

    /** Where the body's first node starts and ends, as token indices. */
    private static int[] firstNode(List<Token> body, Token type) throws ModelException {
        int start = 0;
        while (start < body.size() && body.get(start).isIdent("ROUTE")) {
            start += 8; // ROUTE Node . field TO Node . field
        }
        int at = start;
        if (at < body.size() && body.get(at).isIdent("DEF")) {
            at += 2;
        }
        if (at + 1 >= body.size() || !body.get(at + 1).is(Type.OPEN_BRACE)) {
            throw new ModelException(Kind.MALFORMED, type.location() + ": the body of PROTO " + type.text()
                    + " does not start with a node");
        }
        int depth = 0;
        for (int i = at + 1; i < body.size(); i++) {
            depth += body.get(i).is(Type.OPEN_BRACE) ? 1 : body.get(i).is(Type.CLOSE_BRACE) ? -1 : 0;
            if (depth == 0) {
                return new int[] {start, i + 1};
            }
        }
        throw new ModelException(Kind.MALFORMED, type.location() + ": the body of PROTO " + type.text()
                + " is not closed");
    }

    /** The tokens of one field value: a bracketed list, a node, or a run of numbers, a string or a word. */
    private static List<Token> value(VrmlTokenizer tokens) throws ModelException {
        List<Token> value = new ArrayList<>();
        Token next = tokens.peek();
        if (next.is(Type.OPEN_BRACKET) || next.is(Type.IDENT) && tokens.peek(1).is(Type.OPEN_BRACE)
                || next.isIdent("DEF")) {
            if (next.isIdent("DEF")) {
                value.add(tokens.next());
                value.add(tokens.next());
            }
            balanced(tokens, value);
        } else if (next.isIdent("USE")) {
            value.add(tokens.next());
            value.add(tokens.next());
        } else if (next.is(Type.NUMBER)) {
            while (tokens.peek().is(Type.NUMBER)) {
                value.add(tokens.next());
            }
        } else {
            value.add(tokens.next());
        }
        return value;
    }

    /** A node (its type and braces) or a bracketed list, whole. */
    private static void balanced(VrmlTokenizer tokens, List<Token> into) throws ModelException {
        int depth = 0;
        do {
            Token token = tokens.next();
            if (token.is(Type.EOF)) {
                throw new ModelException(Kind.MALFORMED, token.location() + ": a value never closed");
            }
            into.add(token);
            if (token.is(Type.OPEN_BRACE) || token.is(Type.OPEN_BRACKET)) {
                depth++;
            } else if (token.is(Type.CLOSE_BRACE) || token.is(Type.CLOSE_BRACKET)) {
                depth--;
            }
        } while (depth > 0 || into.get(into.size() - 1).is(Type.IDENT));
    }

    private static void expect(VrmlTokenizer tokens, Type type, String what) throws ModelException {
        Token token = tokens.next();
        if (!token.is(type)) {
            throw new ModelException(Kind.MALFORMED, token.location() + ": expected " + what + " but found "
                    + token.quoted());
        }
    }
}
