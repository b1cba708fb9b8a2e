package io.orchard.viewer.model.x3d;

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

    private XmlElement element;
    private final ParseBudget budget;
    private final FieldReader reader;
    private final SceneDescription.Collector scene;
    private final Deque<Frame> stack = new ArrayDeque<>();
    private final List<SceneNode> roots = new ArrayList<>();
    private final Set<String> warned;
    private final ModelFiles files;
    private final String file;

    private X3dParser(ParseBudget budget, SceneDescription.Collector scene,
                      ModelFiles files, String file, Set<String> warned) {
        this.budget = budget;
        this.reader = new FieldReader(budget);
        this.scene = scene;
        this.files = files;
        this.file = file;
        this.warned = warned;
    }

    /** Parses an X3D XML file, checking it against {@code limits}. */
    public static SceneDescription parse(byte[] bytes, ModelLimits limits) throws ModelException {
        return parse(bytes, limits, ModelFiles.none());
    }

    /**
     * {@link #parse(byte[], ModelLimits)} for a file of a zip: an ImageTexture's url naming another
     * file of the archive is read from it, and an {@code Inline} of an X3D file of the archive
     * becomes a Group of that file's nodes, whose DEF names and ROUTEs join the model's.
     */
    public static SceneDescription parse(byte[] bytes, ModelLimits limits, ModelFiles files)
            throws ModelException {
        ParseBudget.checkSize(bytes, limits, "X3D");
        ParseBudget budget = new ParseBudget(limits);
        SceneDescription.Collector scene = new SceneDescription.Collector(budget);
        List<SceneNode> roots = read(bytes, budget, scene, files, null, new HashSet<>());
        return scene.finish(roots);
    }

    private static List<SceneNode> read(byte[] bytes, ParseBudget budget,
                                        SceneDescription.Collector scene, ModelFiles files,
                                        String file, Set<String> warned) throws ModelException {
        XMLStreamReader xml = null;
        String what = file == null ? "X3D" : "X3D file '" + file + "'";
        XmlElement root;
        try {
            xml = factory().createXMLStreamReader(new ByteArrayInputStream(bytes));
            root = tree(xml, file, budget.limits().maxDepth() + 2);
        } catch (XMLStreamException e) {
            throw new ModelException(Kind.MALFORMED, what + " is not well-formed XML: "
                    + oneLine(e.getMessage()), e);
        } catch (RuntimeException e) {
            // The JDK parser reports some malformed input as unchecked exceptions.
            throw new ModelException(Kind.MALFORMED, what + " could not be read: " + e, e);
        } finally {
            if (xml != null) {
                try {
                    xml.close();
                } catch (XMLStreamException ignored) {
                    // Nothing is held open: the input is a byte array.
                }
            }
        }
        X3dProtos.expand(root, budget.limits());
        X3dParser parser = new X3dParser(budget, scene, files, file, warned);
        parser.stack.push(new Frame(FrameKind.SKIP, null, null, root.location(), null));
        for (XmlElement child : root.children()) {
            parser.walk(child);
        }
        return parser.roots;
    }

    /** Visits an element and everything below it, as the events of a stream would. */
    private void walk(XmlElement at) throws ModelException {
        element = at;
        if (start()) {
            for (XmlElement child : at.children()) {
                walk(child);
            }
        }
        element = at;
        end();
    }

    /**
     * Reads the document into elements, refusing entities and elements nested deeper than
     * {@code maxDepth}.
     */
    private static XmlElement tree(XMLStreamReader xml, String file, int maxDepth)
            throws XMLStreamException, ModelException {
        Deque<XmlElement> open = new ArrayDeque<>();
        XmlElement root = null;
        while (xml.hasNext()) {
            int event = xml.next();
            switch (event) {
                case XMLStreamConstants.DTD -> checkDoctype(xml, file);
                case XMLStreamConstants.ENTITY_REFERENCE -> throw new ModelException(Kind.UNSAFE,
                        where(xml, file) + ": entity reference &" + xml.getLocalName()
                                + "; refused (X3D models may not use entities)");
                case XMLStreamConstants.START_ELEMENT -> {
                    Map<String, String> attributes = new LinkedHashMap<>();
                    for (int i = 0; i < xml.getAttributeCount(); i++) {
                        String prefix = xml.getAttributePrefix(i);
                        if (prefix == null || prefix.isEmpty()) {
                            attributes.put(xml.getAttributeLocalName(i), xml.getAttributeValue(i));
                        }
                    }
                    XmlElement element = new XmlElement(xml.getLocalName(), attributes,
                            where(xml, file));
                    if (root == null) {
                        if (!element.name().equals("X3D")) {
                            throw new ModelException(Kind.MALFORMED, element.location()
                                    + ": an X3D document's root element is <X3D>, not <"
                                    + element.name() + ">");
                        }
                        root = element;
                    } else {
                        if (open.size() > maxDepth) {
                            throw new ModelException(Kind.TOO_LARGE, element.location() + ": <"
                                    + element.name() + ">: nesting deeper than " + (maxDepth - 2)
                                    + " levels");
                        }
                        open.peek().children().add(element);
                    }
                    open.push(element);
                }
                case XMLStreamConstants.END_ELEMENT -> open.pop();
                default -> { }
            }
        }
        if (root == null) {
            throw new ModelException(Kind.MALFORMED, "X3D document has no root element");
        }
        return root;
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

    private static void checkDoctype(XMLStreamReader xml, String file) throws ModelException {
        String doctype = xml.getText();
        if (doctype != null && doctype.contains("<!ENTITY")) {
            throw new ModelException(Kind.UNSAFE, where(xml, file) + ": the DOCTYPE declares"
                    + " entities; entity declarations are refused (external entities and entity"
                    + " expansion are never processed)");
        }
    }

    /** Opens the current element; false when its children are not to be visited. */
    private boolean start() throws ModelException {
        String name = element.name();
        String location = where();
        Frame parent = stack.peek();
        boolean topLevel = stack.size() == 1;
        if (topLevel && name.equals("Scene")) {
            stack.push(new Frame(FrameKind.SCENE, null, null, location, null));
            return true;
        }
        budget.enter(location + ": <" + name + ">");
        if (topLevel || parent.kind() == FrameKind.SKIP || parent.kind() == FrameKind.ROUTE) {
            stack.push(skip(location));
            return true;
        }
        if (parent.kind() == FrameKind.USE) {
            throw new ModelException(Kind.MALFORMED, location + ": <" + name + "> inside a USE"
                    + " element (" + parent.location() + "); a USE has no children");
        }
        if (name.equals("ROUTE")) {
            scene.route(new SceneDescription.Route(required("fromNode"), required("fromField"),
                    required("toNode"), required("toField"), location));
            stack.push(new Frame(FrameKind.ROUTE, null, null, location, null));
            return true;
        }
        if (SKIPPED.contains(name)) {
            if (warned.add(name)) {
                LOG.warn("{}: <{}> is not supported; it is ignored", location, name);
            }
            stack.push(skip(location));
            return true;
        }
        String container = attribute("containerField");
        if (container == null) {
            container = NodeSchema.defaultContainerField(name);
        }
        if (name.equals("Inline") && files.any() && attribute("USE") == null) {
            inline(container, location);
            return false;
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
            return true;
        }
        budget.addNodes(1, location + ": <" + name + ">");
        SceneNode node = new SceneNode(name, location);
        String def = attribute("DEF");
        if (def != null) {
            node.setDefName(def);
        }
        for (Map.Entry<String, String> attribute : element.attributes().entrySet()) {
            if (!NON_FIELD_ATTRIBUTES.contains(attribute.getKey())) {
                fieldAttribute(node, attribute.getKey(), attribute.getValue(), location);
            }
        }
        stack.push(new Frame(FrameKind.NODE, node, container, location,
                new LinkedHashMap<>()));
        return true;
    }

    /** An Inline of a file of the same zip: a Group holding that file's nodes. */
    private void inline(String container, String location) throws ModelException {
        budget.addNodes(1, location + ": <Inline>");
        SceneNode group = new SceneNode("Group", location);
        String def = attribute("DEF");
        if (def != null) {
            group.setDefName(def);
        }
        List<String> urls = new ArrayList<>();
        String url = attribute("url");
        if (url != null) {
            java.util.regex.Matcher quoted = java.util.regex.Pattern.compile("\"([^\"]*)\"").matcher(url);
            while (quoted.find()) {
                urls.add(quoted.group(1));
            }
            if (urls.isEmpty() && !url.isBlank()) {
                urls.add(url.strip());
            }
        }
        ModelFiles.Inlined inlined = files.inline(urls, location + ": <Inline>");
        if (inlined.format() != io.orchard.protocol.value.ModelFormat.X3D) {
            throw new ModelException(Kind.UNSUPPORTED, location + ": <Inline> of '"
                    + inlined.path() + "': an X3D file inlines X3D files only");
        }
        List<SceneNode> children = read(inlined.bytes(), budget, scene, inlined.files(),
                inlined.path(), warned);
        Map<String, List<SceneNode>> lists = new LinkedHashMap<>();
        lists.put("children", new ArrayList<>(children));
        stack.push(new Frame(FrameKind.NODE, group, container, location, lists));
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
        Object read = reader.readAttribute(value, def, node, location);
        if (node.is("ImageTexture") && name.equals("url") && read instanceof List<?> urls) {
            read = files.embedded(urls.stream().map(String::valueOf).toList(), location + ": "
                    + node.label() + " field url");
        }
        node.set(name, read);
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
        return element.attribute(name);
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
        return element.location();
    }

    private static String where(XMLStreamReader xml, String file) {
        Location location = xml.getLocation();
        return (file == null ? "" : file + " ") + "line " + location.getLineNumber() + ":" + location.getColumnNumber();
    }

    private static String oneLine(String message) {
        return message == null ? "" : message.replaceAll("\\s*\\R\\s*", " ").strip();
    }

    private static String abbreviate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 37) + "...";
    }
}
