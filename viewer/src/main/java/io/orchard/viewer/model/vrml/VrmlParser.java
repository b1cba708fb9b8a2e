package io.orchard.viewer.model.vrml;

import io.orchard.viewer.model.FieldDef;
import io.orchard.viewer.model.FieldType;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelFiles;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.NodeKind;
import io.orchard.viewer.model.NodeSchema;
import io.orchard.viewer.model.ParseBudget;
import io.orchard.viewer.model.SceneDescription;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Token;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Type;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Parses the VRML97 classic encoding into a {@link SceneDescription}: a recursive-descent parser
 * over {@link VrmlTokenizer} whose recursion is bounded by {@link ModelLimits#maxDepth()}, so
 * that no nesting, however deep, can overflow the stack.
 *
 * <p>Node types outside {@link NodeSchema} are parsed generically (their DEF names stay usable)
 * and later skipped. PROTO and EXTERNPROTO declarations are skipped with a warning, so their
 * instances become such unknown nodes; nothing named by a URL is ever fetched.
 */
public final class VrmlParser {

    private static final Logger LOG = LoggerFactory.getLogger(VrmlParser.class);
    private static final String HEADER = "#VRML V2.0 utf8";
    private static final Set<String> INTERFACE_WORDS =
            Set.of("eventIn", "eventOut", "field", "exposedField");

    private final VrmlTokenizer tokens;
    private final ParseBudget budget;
    private final FieldReader reader;
    private final SceneDescription.Collector scene;
    private final Set<String> warned = new HashSet<>();
    private final ModelFiles files;
    private final VrmlProtos protos;
    private int instancesOpen;

    private VrmlParser(String text, ModelLimits limits, ModelFiles files) {
        this.files = files;
        this.protos = new VrmlProtos(limits.maxNodes());
        this.tokens = new VrmlTokenizer(text);
        this.budget = new ParseBudget(limits);
        this.reader = new FieldReader(budget);
        this.scene = new SceneDescription.Collector(budget);
    }

    /** Parses a VRML97 file, checking it against {@code limits}; the bytes must be UTF-8. */
    public static SceneDescription parse(byte[] bytes, ModelLimits limits) throws ModelException {
        return parse(bytes, limits, ModelFiles.none());
    }

    /**
     * {@link #parse(byte[], ModelLimits)} for a file of a zip: an ImageTexture's url naming another
     * file of the archive is read from it.
     */
    public static SceneDescription parse(byte[] bytes, ModelLimits limits, ModelFiles files)
            throws ModelException {
        ParseBudget.checkSize(bytes, limits, "VRML97");
        String text = decode(bytes);
        if (text.startsWith("\uFEFF")) {
            text = text.substring(1);
        }
        if (!text.startsWith(HEADER)) {
            String firstLine = text.lines().findFirst().orElse("");
            if (firstLine.startsWith("#VRML V1.0") || firstLine.startsWith("#X3D")) {
                throw new ModelException(Kind.UNSUPPORTED, "line 1: '" + abbreviate(firstLine)
                        + "' is not VRML97; only '" + HEADER + "' files are read here");
            }
            throw new ModelException(Kind.MALFORMED, "line 1: a VRML97 file starts with '"
                    + HEADER + "' but this one starts with '" + abbreviate(firstLine) + "'");
        }
        return new VrmlParser(text, limits, files).scene();
    }

    private SceneDescription scene() throws ModelException {
        List<SceneNode> roots = new ArrayList<>();
        while (!tokens.peek().is(Type.EOF)) {
            if (!statement()) {
                SceneNode node = nodeStatement();
                if (node == null) {
                    throw new ModelException(Kind.MALFORMED, tokens.location()
                            + ": NULL is not a node");
                }
                roots.add(node);
            }
        }
        return scene.finish(roots);
    }

    /** Handles a ROUTE, PROTO or EXTERNPROTO statement if one comes next. */
    private boolean statement() throws ModelException {
        Token token = tokens.peek();
        if (token.isIdent("ROUTE")) {
            route();
        } else if (token.isIdent("PROTO")) {
            protos.declare(tokens);
        } else if (token.isIdent("EXTERNPROTO")) {
            skipExternProto();
        } else {
            return false;
        }
        return true;
    }

    /** {@code DEF name node}, {@code USE name}, {@code NULL} (returned as null) or a node. */
    private SceneNode nodeStatement() throws ModelException {
        Token token = tokens.next();
        if (token.isIdent("DEF")) {
            String name = identifier("a name after DEF");
            SceneNode node = node(tokens.next(), name);
            scene.define(name, node);
            return node;
        }
        if (token.isIdent("USE")) {
            String name = identifier("a name after USE");
            SceneNode node = scene.use(name, token.location());
            budget.checkHeight(node, budget.depth() + 1, token.location());
            return node;
        }
        if (token.isIdent("NULL")) {
            return null;
        }
        return node(token, null);
    }

    private SceneNode node(Token typeToken, String defName) throws ModelException {
        if (!typeToken.is(Type.IDENT) || !tokens.peek().is(Type.OPEN_BRACE)) {
            Token found = typeToken.is(Type.IDENT) ? tokens.peek() : typeToken;
            throw new ModelException(Kind.MALFORMED, found.location()
                    + ": expected a node (a type name and '{') but found " + found.quoted()
                    + (typeToken.is(Type.IDENT) ? " after '" + typeToken.text() + "'" : ""));
        }
        if (protos.declares(typeToken.text())) {
            if (++instancesOpen > VrmlProtos.MAX_NESTING) {
                throw new ModelException(Kind.TOO_LARGE, typeToken.location() + ": PROTO instances nest deeper than "
                        + VrmlProtos.MAX_NESTING + " (does a PROTO instantiate itself?)");
            }
            try {
                protos.expand(typeToken, defName, tokens);
                return nodeStatement();
            } finally {
                instancesOpen--;
            }
        }
        String where = typeToken.location();
        protos.isExtern(typeToken.text(), where);
        budget.enter(where + ": " + typeToken.text());
        budget.addNodes(1, where + ": " + typeToken.text());
        tokens.next();
        SceneNode node = new SceneNode(typeToken.text(), where);
        node.setDefName(defName);
        if (!node.isKnown() && warned.add("type:" + node.typeName())) {
            LOG.debug("{}: node type {} is not built by this viewer", where, node.typeName());
        }
        while (true) {
            Token token = tokens.peek();
            if (token.is(Type.CLOSE_BRACE)) {
                tokens.next();
                break;
            }
            if (token.is(Type.EOF)) {
                throw new ModelException(Kind.MALFORMED, token.location() + ": " + node.label()
                        + " never closed (missing '}'); the file is truncated");
            }
            if (statement()) {
                continue;
            }
            Token name = tokens.next();
            if (!name.is(Type.IDENT)) {
                throw new ModelException(Kind.MALFORMED, name.location() + ": " + node.label()
                        + ": expected a field name but found " + name.quoted());
            }
            field(node, name);
        }
        budget.complete(node, where);
        budget.exit();
        return node;
    }

    private void field(SceneNode node, Token name) throws ModelException {
        FieldDef def = node.type().flatMap(t -> t.field(name.text())).orElse(null);
        if (def == null) {
            if (node.isKnown() && warned.add(node.typeName() + "." + name.text())) {
                LOG.warn("{}: {} has no field '{}'; its value is ignored", name.location(),
                        node.label(), name.text());
            }
            genericValue(node, name);
            return;
        }
        if (!def.access().canInitialize()) {
            throw new ModelException(Kind.BAD_VALUE, name.location() + ": " + node.label()
                    + " field " + def.name() + " is an " + (def.access() == FieldDef.Access
                    .EVENT_IN ? "eventIn" : "eventOut") + " and cannot be given a value");
        }
        if (def.type() == FieldType.SFNODE) {
            Token at = tokens.peek();
            SceneNode child = nodeStatement();
            checkKind(node, def, child, at);
            node.set(def.name(), child);
        } else if (def.type() == FieldType.MFNODE) {
            node.set(def.name(), nodeList(node, def));
        } else if (node.is("ImageTexture") && def.name().equals("url")) {
            List<String> urls = ((List<?>) reader.readVrml(tokens, def, node)).stream()
                    .map(String::valueOf).toList();
            node.set(def.name(), files.embedded(urls, name.location() + ": " + node.label()
                    + " field url"));
        } else {
            node.set(def.name(), reader.readVrml(tokens, def, node));
        }
    }

    private List<SceneNode> nodeList(SceneNode node, FieldDef def) throws ModelException {
        List<SceneNode> children = new ArrayList<>();
        if (!tokens.peek().is(Type.OPEN_BRACKET)) {
            Token at = tokens.peek();
            SceneNode child = nodeStatement();
            checkKind(node, def, child, at);
            if (child != null) {
                children.add(child);
            }
            return List.copyOf(children);
        }
        tokens.next();
        while (true) {
            Token at = tokens.peek();
            if (at.is(Type.CLOSE_BRACKET)) {
                tokens.next();
                return List.copyOf(children);
            }
            if (at.is(Type.EOF)) {
                throw new ModelException(Kind.MALFORMED, at.location() + ": " + node.label()
                        + " field " + def.name() + " never closed (missing ']')");
            }
            if (statement()) {
                continue;
            }
            SceneNode child = nodeStatement();
            checkKind(node, def, child, at);
            if (child != null) {
                children.add(child);
            }
        }
    }

    private static void checkKind(SceneNode parent, FieldDef def, SceneNode child, Token at)
            throws ModelException {
        if (child == null || def.accepts() == NodeKind.ANY || child.type().isEmpty()) {
            return;
        }
        NodeKind kind = child.type().get().kind();
        if (kind != def.accepts()) {
            throw new ModelException(Kind.BAD_VALUE, at.location() + ": " + parent.label()
                    + " field " + def.name() + ": expected " + def.accepts().description()
                    + " but found " + child.label());
        }
    }

    /**
     * Reads a value without knowing its type, keeping any nodes in it: for node types and fields
     * outside the schema. Script-style interface declarations are read too.
     */
    private void genericValue(SceneNode node, Token name) throws ModelException {
        if (INTERFACE_WORDS.contains(name.text())) {
            identifier("a field type after " + name.text());
            String fieldName = identifier("a field name");
            if (name.text().equals("field") || name.text().equals("exposedField")) {
                genericValue(node, new Token(Type.IDENT, fieldName, name.location()));
            }
            return;
        }
        List<SceneNode> nodes = new ArrayList<>();
        Token token = tokens.peek();
        if (token.is(Type.OPEN_BRACKET)) {
            tokens.next();
            while (!tokens.peek().is(Type.CLOSE_BRACKET)) {
                if (isNodeStart()) {
                    addIfPresent(nodes, nodeStatement());
                } else if (isAtom(tokens.peek())) {
                    Token atom = tokens.next();
                    budget.addValue(() -> atom.location() + ": " + node.label());
                } else if (!statement()) {
                    Token bad = tokens.peek();
                    throw new ModelException(Kind.MALFORMED, bad.location() + ": "
                            + node.label() + " field " + name.text()
                            + ": expected a value but found " + bad.quoted());
                }
            }
            tokens.next();
        } else if (isNodeStart()) {
            addIfPresent(nodes, nodeStatement());
        } else if (token.isIdent("IS")) {
            tokens.next();
            identifier("a field name after IS");
        } else {
            int atoms = 0;
            while (isAtom(tokens.peek())) {
                Token atom = tokens.next();
                budget.addValue(() -> atom.location() + ": " + node.label());
                atoms++;
            }
            if (atoms == 0) {
                throw new ModelException(Kind.MALFORMED, token.location() + ": " + node.label()
                        + " field " + name.text() + ": expected a value but found "
                        + token.quoted());
            }
        }
        if (!nodes.isEmpty()) {
            node.set(name.text(), List.copyOf(nodes));
        }
    }

    private static void addIfPresent(List<SceneNode> nodes, SceneNode node) {
        if (node != null) {
            nodes.add(node);
        }
    }

    private boolean isNodeStart() throws ModelException {
        Token token = tokens.peek();
        if (token.isIdent("DEF") || token.isIdent("USE")) {
            return true;
        }
        return token.is(Type.IDENT) && tokens.peek(1).is(Type.OPEN_BRACE);
    }

    private static boolean isAtom(Token token) {
        return token.is(Type.NUMBER) || token.is(Type.STRING) || token.isIdent("TRUE")
                || token.isIdent("FALSE") || token.isIdent("NULL");
    }

    private void route() throws ModelException {
        Token start = tokens.next();
        String fromNode = identifier("a node name after ROUTE");
        expectPeriod(start);
        String fromField = identifier("an eventOut name");
        Token to = tokens.next();
        if (!to.isIdent("TO")) {
            throw new ModelException(Kind.MALFORMED, to.location()
                    + ": ROUTE needs the form 'ROUTE Node.field TO Node.field' but found "
                    + to.quoted() + " where TO belongs");
        }
        String toNode = identifier("a node name after TO");
        expectPeriod(start);
        String toField = identifier("an eventIn name");
        scene.route(new SceneDescription.Route(fromNode, fromField, toNode, toField,
                start.location()));
    }

    private void expectPeriod(Token route) throws ModelException {
        Token token = tokens.next();
        if (!token.is(Type.PERIOD)) {
            throw new ModelException(Kind.MALFORMED, token.location() + ": ROUTE (" + route
                    .location() + ") needs 'Node.field' but found " + token.quoted());
        }
    }

    private void skipExternProto() throws ModelException {
        Token start = tokens.next();
        String name = identifier("a name after EXTERNPROTO");
        LOG.warn("{}: EXTERNPROTO {} is refused: its prototype is in another file, never fetched; its"
                + " instances are not drawn", start.location(), name);
        protos.extern(name, start.location());
        skipBalanced(Type.OPEN_BRACKET, start);
        if (tokens.peek().is(Type.OPEN_BRACKET)) {
            skipBalanced(Type.OPEN_BRACKET, start);
        } else if (tokens.peek().is(Type.STRING)) {
            tokens.next();
        }
    }

    /** Skips one bracketed group, nested brackets included, without recursion. */
    private void skipBalanced(Type open, Token start) throws ModelException {
        Token first = tokens.next();
        if (!first.is(open)) {
            throw new ModelException(Kind.MALFORMED, first.location() + ": "
                    + start.text() + " (" + start.location() + ") expected '"
                    + (open == Type.OPEN_BRACE ? "{" : "[") + "' but found " + first.quoted());
        }
        int depth = 1;
        while (depth > 0) {
            Token token = tokens.next();
            switch (token.type()) {
                case OPEN_BRACE, OPEN_BRACKET -> depth++;
                case CLOSE_BRACE, CLOSE_BRACKET -> depth--;
                case EOF -> throw new ModelException(Kind.MALFORMED, token.location() + ": "
                        + start.text() + " (" + start.location() + ") never closed");
                default -> { }
            }
        }
    }

    private String identifier(String expected) throws ModelException {
        Token token = tokens.next();
        if (!token.is(Type.IDENT)) {
            throw new ModelException(Kind.MALFORMED, token.location() + ": expected "
                    + expected + " but found " + token.quoted());
        }
        return token.text();
    }

    private static String decode(byte[] bytes) throws ModelException {
        try {
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new ModelException(Kind.MALFORMED, "VRML97 text is not valid UTF-8: "
                    + e.getMessage(), e);
        }
    }

    private static String abbreviate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 37) + "...";
    }
}
