package io.orchard.agents.model;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.XMLConstants;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;

/**
 * Reads the nodes of an X3D (XML encoding) or VRML97 file into {@link Node}s, leniently: a type it
 * does not know is read like any other, prototypes are skipped (their instances are nodes of an
 * unknown type), and nothing outside the bytes is read (no DTD, no entities, no URL).
 */
final class SceneReader {

    private static final Set<String> X3D_SKIPPED = Set.of("ProtoDeclare", "ExternProtoDeclare", "ROUTE", "IS",
            "fieldValue", "field", "connect");
    private static final int MAX_DEPTH = 256;

    /** What a file holds: its top-level nodes, its length unit if it declares one, and what was skipped. */
    record Scene(List<Node> roots, String unitName, double metresPerUnit, boolean unitDeclared, List<String> notes) {
    }

    private SceneReader() {
    }

    static Scene x3d(byte[] bytes) throws IOException {
        XMLInputFactory factory = XMLInputFactory.newDefaultFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        factory.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        factory.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        List<Node> roots = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        Map<String, Node> defs = new HashMap<>();
        Deque<Node> open = new ArrayDeque<>();
        String unitName = "metre";
        double perUnit = 1;
        boolean declared = false;
        int skipping = 0;
        int protos = 0;
        try {
            XMLStreamReader xml = factory.createXMLStreamReader(new ByteArrayInputStream(bytes));
            boolean inScene = false;
            while (xml.hasNext()) {
                int event = xml.next();
                if (event == XMLStreamConstants.START_ELEMENT) {
                    String name = xml.getLocalName();
                    if (skipping > 0 || X3D_SKIPPED.contains(name)) {
                        skipping++;
                        protos += name.equals("ProtoDeclare") || name.equals("ExternProtoDeclare") ? 1 : 0;
                    } else if (name.equals("unit") && "length".equals(xml.getAttributeValue(null, "category"))) {
                        declared = true;
                        unitName = String.valueOf(xml.getAttributeValue(null, "name"));
                        perUnit = parse(xml.getAttributeValue(null, "conversionFactor"), 1);
                    } else if (name.equals("Scene")) {
                        inScene = true;
                    } else if (inScene) {
                        if (open.size() >= MAX_DEPTH) {
                            throw new IOException("X3D nests deeper than " + MAX_DEPTH + " elements");
                        }
                        Node node = x3dNode(xml, defs);
                        if (open.isEmpty()) {
                            roots.add(node);
                        } else {
                            open.peek().add("children", node);
                        }
                        open.push(node);
                    }
                } else if (event == XMLStreamConstants.END_ELEMENT) {
                    if (skipping > 0) {
                        skipping--;
                    } else if (xml.getLocalName().equals("Scene")) {
                        inScene = false;
                    } else if (inScene && !open.isEmpty()) {
                        open.pop();
                    }
                }
            }
        } catch (XMLStreamException e) {
            throw new IOException("X3D is not well-formed XML: " + e.getMessage(), e);
        }
        if (protos > 0) {
            notes.add(protos + " prototype declaration(s) skipped: the nodes of their instances are not listed or"
                    + " measured here (viewers expand X3D prototypes)");
        }
        return new Scene(roots, unitName, perUnit, declared, notes);
    }

    private static Node x3dNode(XMLStreamReader xml, Map<String, Node> defs) {
        String use = xml.getAttributeValue(null, "USE");
        if (use != null && defs.containsKey(use)) {
            // The same node again: measured again where it is used, never listed twice.
            Node used = new Node(defs.get(use).type, null);
            used.fields.putAll(defs.get(use).fields);
            used.children.putAll(defs.get(use).children);
            return used;
        }
        Node node = new Node(xml.getLocalName(), xml.getAttributeValue(null, "DEF"));
        for (int i = 0; i < xml.getAttributeCount(); i++) {
            node.fields.put(xml.getAttributeLocalName(i), xml.getAttributeValue(i));
        }
        if (node.def != null) {
            defs.put(node.def, node);
        }
        return node;
    }

    private static double parse(String text, double otherwise) {
        try {
            return text == null ? otherwise : Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            return otherwise;
        }
    }

    static Scene vrml(byte[] bytes) throws IOException {
        String text = new String(bytes, StandardCharsets.UTF_8);
        if (!text.startsWith("#VRML V2.0")) {
            throw new IOException("not a VRML97 file: it does not start with '#VRML V2.0 utf8'");
        }
        VrmlTokens tokens = new VrmlTokens(text);
        List<Node> roots = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        Map<String, Node> defs = new HashMap<>();
        int protos = 0;
        while (tokens.peek() != null) {
            String token = tokens.peek();
            if (token.equals("PROTO") || token.equals("EXTERNPROTO")) {
                protos++;
                tokens.skipProto();
            } else if (token.equals("ROUTE")) {
                tokens.skip(4);
            } else {
                Node node = vrmlNode(tokens, defs, 0);
                if (node != null) {
                    roots.add(node);
                }
            }
        }
        if (protos > 0) {
            notes.add(protos + " PROTO declaration(s) skipped: the nodes of their instances are not listed or"
                    + " measured here");
        }
        return new Scene(roots, "metre", 1, false, notes);
    }

    private static Node vrmlNode(VrmlTokens tokens, Map<String, Node> defs, int depth) throws IOException {
        if (depth > MAX_DEPTH) {
            throw new IOException("VRML97 nests deeper than " + MAX_DEPTH + " nodes");
        }
        String token = tokens.next();
        if (token.equals("USE")) {
            return defs.get(tokens.next());
        }
        String def = null;
        if (token.equals("DEF")) {
            def = tokens.next();
            token = tokens.next();
        }
        if (!"{".equals(tokens.peek())) {
            // Not a node: a stray word or value; skipped.
            return null;
        }
        tokens.next();
        Node node = new Node(token, def);
        while (tokens.peek() != null && !tokens.peek().equals("}")) {
            String field = tokens.next();
            if (field.equals("ROUTE")) {
                tokens.skip(3);
                continue;
            }
            if (field.equals("PROTO") || field.equals("EXTERNPROTO")) {
                tokens.skipProto();
                continue;
            }
            vrmlValue(tokens, node, field, defs, depth);
        }
        tokens.next();
        if (def != null) {
            defs.put(def, node);
        }
        return node;
    }

    private static void vrmlValue(VrmlTokens tokens, Node node, String field, Map<String, Node> defs, int depth)
            throws IOException {
        String next = tokens.peek();
        if (next == null) {
            return;
        }
        if (next.equals("[")) {
            tokens.next();
            StringBuilder values = new StringBuilder();
            while (tokens.peek() != null && !tokens.peek().equals("]")) {
                if (startsNode(tokens)) {
                    Node child = vrmlNode(tokens, defs, depth + 1);
                    if (child != null) {
                        node.add(field, child);
                    }
                } else {
                    values.append(tokens.next()).append(' ');
                }
            }
            tokens.next();
            node.fields.put(field, values.toString().trim());
        } else if (startsNode(tokens)) {
            Node child = vrmlNode(tokens, defs, depth + 1);
            if (child != null) {
                node.add(field, child);
            }
        } else {
            StringBuilder values = new StringBuilder();
            while (tokens.peek() != null && isValue(tokens.peek())) {
                values.append(tokens.next()).append(' ');
            }
            node.fields.put(field, values.toString().trim());
        }
    }

    private static boolean startsNode(VrmlTokens tokens) {
        String next = tokens.peek();
        return next.equals("DEF") || next.equals("USE") || Character.isLetter(next.charAt(0))
                && !isValue(next) && "{".equals(tokens.peekSecond());
    }

    private static boolean isValue(String token) {
        char c = token.charAt(0);
        return Character.isDigit(c) || c == '-' || c == '+' || c == '.' || c == '"' || token.equals("TRUE")
                || token.equals("FALSE") || token.equals("NULL");
    }

    /** VRML97's tokens: braces and brackets, strings, and words; commas and comments are white space. */
    private static final class VrmlTokens {

        private final List<String> tokens = new ArrayList<>();
        private int at;

        VrmlTokens(String text) {
            int i = text.indexOf('\n') + 1;
            while (i > 0 && i < text.length()) {
                char c = text.charAt(i);
                if (Character.isWhitespace(c) || c == ',') {
                    i++;
                } else if (c == '#') {
                    while (i < text.length() && text.charAt(i) != '\n') {
                        i++;
                    }
                } else if ("{}[]".indexOf(c) >= 0) {
                    tokens.add(String.valueOf(c));
                    i++;
                } else if (c == '"') {
                    int end = i + 1;
                    while (end < text.length() && text.charAt(end) != '"') {
                        end += text.charAt(end) == '\\' ? 2 : 1;
                    }
                    tokens.add(text.substring(i, Math.min(end + 1, text.length())));
                    i = end + 1;
                } else {
                    int end = i;
                    while (end < text.length() && !Character.isWhitespace(text.charAt(end))
                            && "{}[],#\"".indexOf(text.charAt(end)) < 0) {
                        end++;
                    }
                    tokens.add(text.substring(i, end));
                    i = end;
                }
            }
        }

        String peek() {
            return at < tokens.size() ? tokens.get(at) : null;
        }

        String peekSecond() {
            return at + 1 < tokens.size() ? tokens.get(at + 1) : null;
        }

        String next() throws IOException {
            if (at >= tokens.size()) {
                throw new IOException("VRML97 ends in the middle of a node");
            }
            return tokens.get(at++);
        }

        void skip(int count) {
            at = Math.min(tokens.size(), at + count);
        }

        /** Skips PROTO name [ interface ] { body }, or EXTERNPROTO name [ interface ] url. */
        void skipProto() throws IOException {
            boolean extern = next().equals("EXTERNPROTO");
            next();
            balanced();
            if (extern) {
                if ("[".equals(peek())) {
                    balanced();
                } else {
                    next();
                }
            } else {
                balanced();
            }
        }

        private void balanced() throws IOException {
            int depth = 0;
            do {
                String token = next();
                if (token.equals("[") || token.equals("{")) {
                    depth++;
                } else if (token.equals("]") || token.equals("}")) {
                    depth--;
                }
            } while (depth > 0);
        }
    }
}
