package io.orchard.viewer.model.x3d;

import io.orchard.viewer.model.FieldDef;
import io.orchard.viewer.model.FieldType;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.NodeKind;
import io.orchard.viewer.model.NodeSchema;
import io.orchard.viewer.model.ParseBudget;
import io.orchard.viewer.model.SceneDescription;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.vrml.FieldReader;
import java.io.ByteArrayInputStream;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.XMLConstants;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Parses X3D's XML encoding into a {@link SceneDescription} with the JDK's own StAX parser,
 * configured so that nothing outside the bytes is ever read: no DTD processing, no external
 * entities, no external DTD or schema access. Ordinary X3D files carry a DOCTYPE; it is read
 * and ignored. A DOCTYPE that declares entities (the XXE and "billion laughs" attacks) is refused.
 *
 * <p>The reader is a loop over events with an explicit stack, not recursion; the depth limit
 * stops deep nesting at the first element over it.
 */
public final class X3dParser {

    private static final Logger LOG = LoggerFactory.getLogger(X3dParser.class);
    private static final Set<String> SKIPPED = Set.of("ProtoDeclare", "ExternProtoDeclare",
            "IS", "connect", "field", "fieldValue");
    private static final Set<String> NON_FIELD_ATTRIBUTES =
            Set.of("DEF", "USE", "containerField", "class", "id", "style");

    private enum FrameKind { SCENE, NODE, USE, ROUTE, SKIP }

    /** One open element. MF children collect in {@code lists} until the element ends. */
    private record Frame(FrameKind kind, SceneNode node, String containerField, String location,
                         Map<String, List<SceneNode>> lists) {
    }

    private final XMLStreamReader xml;
    private final ParseBudget budget;
    private final FieldReader reader;
    private final SceneDescription.Collector scene;
    private final Deque<Frame> stack = new ArrayDeque<>();
    private final List<SceneNode> roots = new ArrayList<>();
    private final Set<String> warned = new HashSet<>();

    private X3dParser(XMLStreamReader xml, ModelLimits limits) {
        this.xml = xml;
        this.budget = new ParseBudget(limits);
        this.reader = new FieldReader(budget);
        this.scene = new SceneDescription.Collector(budget);
    }

    /** Parses an X3D XML file, checking it against {@code limits}. */
    public static SceneDescription parse(byte[] bytes, ModelLimits limits) throws ModelException {
        ParseBudget.checkSize(bytes, limits, "X3D");
        XMLStreamReader xml = null;
        try {
            xml = factory().createXMLStreamReader(new ByteArrayInputStream(bytes));
            return new X3dParser(xml, limits).document();
        } catch (XMLStreamException e) {
            throw new ModelException(Kind.MALFORMED, "X3D is not well-formed XML: "
                    + oneLine(e.getMessage()), e);
        } catch (RuntimeException e) {
            // The JDK parser reports some malformed input as unchecked exceptions.
            throw new ModelException(Kind.MALFORMED, "X3D could not be read: " + e, e);
        } finally {
            if (xml != null) {
                try {
                    xml.close();
                } catch (XMLStreamException ignored) {
                    // Nothing is held open: the input is a byte array.
                }
            }
        }
    }

    private static XMLInputFactory factory() {
        // The JDK's built-in implementation, whatever else is on the class path.
        XMLInputFactory factory = XMLInputFactory.newDefaultFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        factory.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        factory.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        factory.setXMLResolver((publicId, systemId, baseUri, namespace) -> {
            throw new XMLStreamException("external resource " + systemId + " refused");
        });
        return factory;
    }

    private SceneDescription document() throws XMLStreamException, ModelException {
        boolean sawRoot = false;
        while (xml.hasNext()) {
            int event = xml.next();
            switch (event) {
                case XMLStreamConstants.DTD -> checkDoctype();
                case XMLStreamConstants.ENTITY_REFERENCE -> throw new ModelException(Kind.UNSAFE,
                        where() + ": entity reference &" + xml.getLocalName()
                                + "; refused (X3D models may not use entities)");
                case XMLStreamConstants.START_ELEMENT -> {
                    if (!sawRoot) {
                        sawRoot = true;
                        if (!xml.getLocalName().equals("X3D")) {
                            throw new ModelException(Kind.MALFORMED, where()
                                    + ": an X3D document's root element is <X3D>, not <"
                                    + xml.getLocalName() + ">");
                        }
                        stack.push(new Frame(FrameKind.SKIP, null, null, where(), null));
                    } else {
                        start();
                    }
                }
                case XMLStreamConstants.END_ELEMENT -> end();
                default -> { }
            }
        }
        if (!sawRoot) {
            throw new ModelException(Kind.MALFORMED, "X3D document has no root element");
        }
        return scene.finish(roots);
    }

    private void checkDoctype() throws ModelException {
        String doctype = xml.getText();
        if (doctype != null && doctype.contains("<!ENTITY")) {
            throw new ModelException(Kind.UNSAFE, where() + ": the DOCTYPE declares entities;"
                    + " entity declarations are refused (external entities and entity"
                    + " expansion are never processed)");
        }
    }

    private void start() throws ModelException {
        String name = xml.getLocalName();
        String location = where();
        Frame parent = stack.peek();
        boolean topLevel = stack.size() == 1;
        if (topLevel && name.equals("Scene")) {
            stack.push(new Frame(FrameKind.SCENE, null, null, location, null));
            return;
        }
        budget.enter(location + ": <" + name + ">");
        if (topLevel || parent.kind() == FrameKind.SKIP || parent.kind() == FrameKind.ROUTE) {
            stack.push(skip(location));
            return;
        }
        if (parent.kind() == FrameKind.USE) {
            throw new ModelException(Kind.MALFORMED, location + ": <" + name + "> inside a USE"
                    + " element (" + parent.location() + "); a USE has no children");
        }
        if (name.equals("ROUTE")) {
            scene.route(new SceneDescription.Route(required("fromNode"), required("fromField"),
                    required("toNode"), required("toField"), location));
            stack.push(new Frame(FrameKind.ROUTE, null, null, location, null));
            return;
        }
        if (SKIPPED.contains(name)) {
            if (warned.add(name)) {
                LOG.warn("{}: <{}> is not supported; it is ignored", location, name);
            }
            stack.push(skip(location));
            return;
        }
        String container = attribute("containerField");
        if (container == null) {
            container = NodeSchema.defaultContainerField(name);
        }
        String use = attribute("USE");
        if (use != null) {
            if (attribute("DEF") != null) {
                throw new ModelException(Kind.MALFORMED, location + ": <" + name
                        + "> has both DEF and USE");
            }
            SceneNode node = scene.use(use, location);
            if (!node.typeName().equals(name)) {
                throw new ModelException(Kind.BAD_VALUE, location + ": <" + name + " USE='"
                        + use + "'> names " + node.label() + ", not a " + name);
            }
            stack.push(new Frame(FrameKind.USE, node, container, location, null));
            return;
        }
        budget.addNodes(1, location + ": <" + name + ">");
        SceneNode node = new SceneNode(name, location);
        String def = attribute("DEF");
        if (def != null) {
            node.setDefName(def);
        }
        for (int i = 0; i < xml.getAttributeCount(); i++) {
            String prefix = xml.getAttributePrefix(i);
            String attribute = xml.getAttributeLocalName(i);
            if ((prefix != null && !prefix.isEmpty()) || NON_FIELD_ATTRIBUTES.contains(attribute)) {
                continue;
            }
            fieldAttribute(node, attribute, xml.getAttributeValue(i), location);
        }
        stack.push(new Frame(FrameKind.NODE, node, container, location,
                new LinkedHashMap<>()));
    }

    private void fieldAttribute(SceneNode node, String name, String value, String location)
            throws ModelException {
        if (!node.isKnown()) {
            return;
        }
        FieldDef def = node.type().get().field(name).orElse(null);
        if (def == null) {
            if (warned.add(node.typeName() + "." + name)) {
                LOG.warn("{}: {} has no field '{}'; the attribute is ignored", location,
                        node.label(), name);
            }
            return;
        }
        if (!def.access().canInitialize() || def.type().isNode()) {
            throw new ModelException(Kind.BAD_VALUE, location + ": " + node.label() + " field "
                    + name + " cannot be given as an attribute value ('" + abbreviate(value)
                    + "')");
        }
        node.set(name, reader.readAttribute(value, def, node, location));
    }

    private void end() throws ModelException {
        Frame frame = stack.pop();
        if (frame.kind() == FrameKind.SCENE || stack.isEmpty()) {
            return;
        }
        if (frame.kind() != FrameKind.NODE && frame.kind() != FrameKind.USE) {
            budget.exit();
            return;
        }
        SceneNode node = frame.node();
        if (frame.kind() == FrameKind.NODE) {
            for (Map.Entry<String, List<SceneNode>> list : frame.lists().entrySet()) {
                node.set(list.getKey(), List.copyOf(list.getValue()));
            }
            budget.complete(node, frame.location());
            node.defName().ifPresent(name -> scene.define(name, node));
        } else {
            budget.checkHeight(node, budget.depth(), frame.location());
        }
        budget.exit();
        attach(stack.peek(), node, frame);
    }

    private void attach(Frame parent, SceneNode child, Frame childFrame) throws ModelException {
        if (parent.kind() == FrameKind.SCENE) {
            roots.add(child);
            return;
        }
        SceneNode node = parent.node();
        String field = childFrame.containerField();
        FieldDef def = node.type().flatMap(t -> t.field(field)).orElse(null);
        if (!node.isKnown()) {
            parent.lists().computeIfAbsent(field, f -> new ArrayList<>()).add(child);
            return;
        }
        if (def == null || !def.type().isNode() || !def.access().canInitialize()) {
            if (!child.isKnown()) {
                // Each such node on its own: the count of what is not drawn matters to its author.
                LOG.warn("{}: {} inside {} is not drawn: {} is a node type this viewer does not"
                        + " support", childFrame.location(), child.typeName(), node.label(),
                        child.typeName());
                return;
            }
            throw new ModelException(Kind.MALFORMED, childFrame.location() + ": " + node.label()
                    + " has no node field '" + field + "' to hold " + child.label());
        }
        if (def.accepts() != NodeKind.ANY && child.isKnown()
                && child.type().get().kind() != def.accepts()) {
            throw new ModelException(Kind.BAD_VALUE, childFrame.location() + ": " + node.label()
                    + " field " + field + ": expected " + def.accepts().description()
                    + " but found " + child.label());
        }
        if (def.type() == FieldType.SFNODE) {
            if (node.has(field)) {
                throw new ModelException(Kind.MALFORMED, childFrame.location() + ": "
                        + node.label() + " field " + field + " holds one node but is given "
                        + "a second one, " + child.label());
            }
            node.set(field, child);
        } else {
            parent.lists().computeIfAbsent(field, f -> new ArrayList<>()).add(child);
        }
    }

    private Frame skip(String location) {
        return new Frame(FrameKind.SKIP, null, null, location, null);
    }

    private String attribute(String name) {
        return xml.getAttributeValue(null, name);
    }

    private String required(String name) throws ModelException {
        String value = attribute(name);
        if (value == null || value.isBlank()) {
            throw new ModelException(Kind.MALFORMED, where() + ": <ROUTE> needs the attribute "
                    + name);
        }
        return value;
    }

    private String where() {
        Location location = xml.getLocation();
        return "line " + location.getLineNumber() + ":" + location.getColumnNumber();
    }

    private static String oneLine(String message) {
        return message == null ? "" : message.replaceAll("\\s*\\R\\s*", " ").strip();
    }

    private static String abbreviate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 37) + "...";
    }
}
