package io.orchard.viewer.model.x3d;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.NodeSchema;
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
 * Expands X3D prototypes in a document before its scene is read: each {@code ProtoInstance}
 * becomes a copy of its {@code ProtoDeclare}'s body, each {@code IS}/{@code connect} in the copy
 * taking the instance's {@code fieldValue} or the interface's default, as a field's value or as its
 * nodes. The first node of the body stands for the instance (its DEF, its containerField); the body's
 * other nodes and ROUTEs follow it where its parent holds children. DEF names inside a body are
 * the instance's own: {@code Leg} in an instance {@code LeftLeg} becomes {@code LeftLeg.Leg}
 * ({@code Proto#2.Leg} for the second unnamed instance of {@code Proto}), so two instances never
 * share a joint. An {@code ExternProtoDeclare}'s prototype lies in another file, which is never
 * fetched: it is refused by name, and its instances are not drawn.
 */
final class X3dProtos {

    private static final Logger LOG = LoggerFactory.getLogger(X3dProtos.class);
    /** Deepest nesting of instances inside prototype bodies: beyond it, a prototype instantiates itself. */
    static final int MAX_NESTING = 16;

    /** A prototype: its fields' defaults (an attribute value, or nodes) and its body. */
    private record Declaration(String name, Map<String, String> values, Map<String, List<XmlElement>> nodes,
                               List<XmlElement> body, String location) {
    }

    private final Map<String, Declaration> protos = new HashMap<>();
    private final Map<String, String> externs = new HashMap<>();
    private final Map<String, Integer> counts = new HashMap<>();
    private final Set<String> warned = new HashSet<>();
    private final int[] budget;
    private final ModelLimits limits;

    private X3dProtos(ModelLimits limits) {
        this.limits = limits;
        this.budget = new int[] {limits.maxNodes()};
    }

    /** Expands every prototype instance under {@code root}, in place. */
    static void expand(XmlElement root, ModelLimits limits) throws ModelException {
        X3dProtos protos = new X3dProtos(limits);
        for (XmlElement child : root.children()) {
            if (child.name().equals("Scene")) {
                protos.declarations(child);
                protos.expandChildren(child, 0);
            }
        }
    }

    /** Takes every declaration out of {@code scene}, at any level where one is written. */
    private void declarations(XmlElement parent) throws ModelException {
        List<XmlElement> kept = new ArrayList<>();
        for (XmlElement child : parent.children()) {
            switch (child.name()) {
                case "ProtoDeclare" -> declare(child);
                case "ExternProtoDeclare" -> {
                    String name = child.attribute("name");
                    externs.put(name, child.location());
                    LOG.warn("{}: ExternProtoDeclare '{}' is refused: its prototype is in another file ({}),"
                            + " which the viewer never fetches; its instances are not drawn", child.location(),
                            name, child.attribute("url"));
                }
                default -> {
                    declarations(child);
                    kept.add(child);
                }
            }
        }
        parent.children().clear();
        parent.children().addAll(kept);
    }

    private void declare(XmlElement declare) throws ModelException {
        String name = declare.attribute("name");
        if (name == null || name.isBlank()) {
            throw new ModelException(Kind.MALFORMED, declare.location() + ": <ProtoDeclare> needs a name");
        }
        Map<String, String> values = new LinkedHashMap<>();
        Map<String, List<XmlElement>> nodes = new LinkedHashMap<>();
        List<XmlElement> body = new ArrayList<>();
        for (XmlElement part : declare.children()) {
            if (part.name().equals("ProtoInterface")) {
                for (XmlElement field : part.children()) {
                    if (field.name().equals("field") && field.attribute("name") != null) {
                        value(field, values, nodes);
                    }
                }
            } else if (part.name().equals("ProtoBody")) {
                declarations(part);
                body.addAll(part.children());
            }
        }
        if (body.isEmpty()) {
            throw new ModelException(Kind.MALFORMED, declare.location() + ": ProtoDeclare '" + name
                    + "' has no ProtoBody with a node in it");
        }
        protos.put(name, new Declaration(name, values, nodes, body, declare.location()));
    }

    /** A field's value as a {@code field} or {@code fieldValue} gives it: an attribute, or nodes. */
    private static void value(XmlElement field, Map<String, String> values, Map<String, List<XmlElement>> nodes) {
        String name = field.attribute("name");
        if (field.attribute("value") != null) {
            values.put(name, field.attribute("value"));
            nodes.remove(name);
        } else if (!field.children().isEmpty()) {
            nodes.put(name, field.children());
            values.remove(name);
        }
    }

    private void expandChildren(XmlElement parent, int nesting) throws ModelException {
        List<XmlElement> expanded = new ArrayList<>();
        for (XmlElement child : parent.children()) {
            if (child.name().equals("ProtoInstance")) {
                expanded.addAll(instance(child, parent, nesting));
            } else {
                expandChildren(child, nesting);
                expanded.add(child);
            }
        }
        parent.children().clear();
        parent.children().addAll(expanded);
    }

    /** The nodes standing for an instance, in its place among its parent's children. */
    private List<XmlElement> instance(XmlElement instance, XmlElement parent, int nesting) throws ModelException {
        String name = instance.attribute("name");
        String where = instance.location() + ": ProtoInstance '" + name + "'";
        Declaration proto = protos.get(name);
        if (proto == null) {
            if (externs.containsKey(name)) {
                LOG.warn("{} is not drawn: its prototype is an ExternProtoDeclare ({}), in a file never fetched",
                        where, externs.get(name));
                return List.of();
            }
            throw new ModelException(Kind.UNKNOWN_NAME, where + " names no ProtoDeclare; the model declares "
                    + (protos.isEmpty() ? "none" : protos.keySet()));
        }
        if (nesting >= MAX_NESTING) {
            throw new ModelException(Kind.TOO_LARGE, where + ": prototype instances nest deeper than "
                    + MAX_NESTING + " (does a prototype instantiate itself?)");
        }
        if (instance.attribute("USE") != null) {
            XmlElement use = new XmlElement(proto.body().get(0).name(), Map.of("USE", instance.attribute("USE")),
                    instance.location());
            container(use, instance);
            return List.of(use);
        }
        Map<String, String> values = new LinkedHashMap<>(proto.values());
        Map<String, List<XmlElement>> nodes = new LinkedHashMap<>(proto.nodes());
        for (XmlElement fieldValue : instance.children()) {
            if (fieldValue.name().equals("fieldValue") && fieldValue.attribute("name") != null) {
                if (!proto.values().containsKey(fieldValue.attribute("name"))
                        && !proto.nodes().containsKey(fieldValue.attribute("name"))
                        && warned.add(name + "." + fieldValue.attribute("name"))) {
                    LOG.warn("{}: fieldValue '{}' is not a field of the prototype, or has no default; it is used"
                            + " where the body connects it", fieldValue.location(), fieldValue.attribute("name"));
                }
                value(fieldValue, values, nodes);
            }
        }
        int count = counts.merge(name, 1, Integer::sum);
        String def = instance.attribute("DEF");
        String scope = def != null ? def : name + "#" + count;
        List<XmlElement> body = new ArrayList<>();
        for (XmlElement node : proto.body()) {
            body.add(copy(node));
        }
        XmlElement first = firstNode(body, where);
        String firstDef = first.attribute("DEF");
        Map<String, String> renamed = new HashMap<>();
        for (XmlElement node : body) {
            collectDefs(node, scope, renamed);
        }
        if (def != null) {
            if (firstDef != null) {
                renamed.put(firstDef, def);
            }
            first.setAttribute("DEF", def);
        }
        for (XmlElement node : body) {
            connect(node, values, nodes, renamed, where);
        }
        container(first, instance);
        XmlElement holder = new XmlElement("ProtoBody", Map.of(), instance.location());
        holder.children().addAll(body);
        expandChildren(holder, nesting + 1);
        List<XmlElement> out = new ArrayList<>();
        boolean holdsChildren = NodeSchema.find(parent.name()).flatMap(t -> t.field("children")).isPresent()
                || parent.name().equals("Scene");
        for (XmlElement node : holder.children()) {
            if (node == first || holdsChildren && "children".equals(containerOf(node))
                    || holdsChildren && node.name().equals("ROUTE")) {
                out.add(node);
            } else if (warned.add(name + ":rest")) {
                LOG.warn("{}: the prototype's nodes after its first, such as <{}>, are not drawn where the"
                        + " instance stands ({}); give them a grouping node", where, node.name(), parent.name());
            }
        }
        return out;
    }

    private static String containerOf(XmlElement node) {
        String container = node.attribute("containerField");
        return container != null ? container : NodeSchema.defaultContainerField(node.name());
    }

    private static void container(XmlElement node, XmlElement instance) {
        String container = instance.attribute("containerField");
        node.setAttribute("containerField", container != null ? container : "children");
    }

    private static XmlElement firstNode(List<XmlElement> body, String where) throws ModelException {
        for (XmlElement node : body) {
            if (!node.name().equals("ROUTE") && !node.name().startsWith("Metadata")) {
                return node;
            }
        }
        throw new ModelException(Kind.MALFORMED, where + ": its prototype's body has no node");
    }

    private XmlElement copy(XmlElement node) throws ModelException {
        XmlElement copy = node.copy(budget);
        if (budget[0] < 0) {
            throw new ModelException(Kind.TOO_LARGE, node.location() + ": prototype instances make more than "
                    + limits.maxNodes() + " nodes");
        }
        return copy;
    }

    /** Renames the DEFs of a body's copy into the instance's scope. */
    private static void collectDefs(XmlElement node, String scope, Map<String, String> renamed) {
        String def = node.attribute("DEF");
        if (def != null) {
            renamed.put(def, scope + "." + def);
            node.setAttribute("DEF", scope + "." + def);
        }
        if (!node.name().equals("ProtoInstance")) {
            for (XmlElement child : node.children()) {
                collectDefs(child, scope, renamed);
            }
        }
    }

    /** Applies the IS connections and the renaming to a body's copy. */
    private void connect(XmlElement node, Map<String, String> values, Map<String, List<XmlElement>> nodes,
                         Map<String, String> renamed, String where) throws ModelException {
        for (String reference : new String[] {"USE", "fromNode", "toNode"}) {
            String name = node.attribute(reference);
            if (name != null && renamed.containsKey(name)) {
                node.setAttribute(reference, renamed.get(name));
            }
        }
        List<XmlElement> kept = new ArrayList<>();
        for (XmlElement child : node.children()) {
            if (!child.name().equals("IS")) {
                connect(child, values, nodes, renamed, where);
                kept.add(child);
                continue;
            }
            for (XmlElement link : child.children()) {
                String nodeField = link.attribute("nodeField");
                String protoField = link.attribute("protoField");
                if (!link.name().equals("connect") || nodeField == null || protoField == null) {
                    continue;
                }
                if (values.containsKey(protoField)) {
                    node.setAttribute(nodeField, values.get(protoField));
                } else if (nodes.containsKey(protoField)) {
                    for (XmlElement given : nodes.get(protoField)) {
                        XmlElement copy = copy(given);
                        copy.setAttribute("containerField", nodeField);
                        kept.add(copy);
                    }
                }
            }
        }
        node.children().clear();
        node.children().addAll(kept);
    }
}
