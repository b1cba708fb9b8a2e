package io.orchard.viewer.model;

import io.orchard.viewer.model.ModelException.Kind;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What a VRML97 or X3D file says, independent of its encoding: the top-level nodes, the DEF
 * names, and the ROUTEs with both ends resolved and type-checked. The scene builder and the event
 * graph start from here.
 */
public final class SceneDescription {

    /** A ROUTE as written. */
    public record Route(String fromNode, String fromField, String toNode, String toField,
                        String location) {

        @Override
        public String toString() {
            return "ROUTE " + fromNode + "." + fromField + " TO " + toNode + "." + toField
                    + " (" + location + ")";
        }
    }

    /** A ROUTE whose ends exist: {@code fromField} can send, {@code toField} can receive. */
    public record ResolvedRoute(SceneNode from, FieldDef fromField, SceneNode to,
                                FieldDef toField) {
    }

    private final List<SceneNode> roots;
    private final Map<String, SceneNode> defs;
    private final List<ResolvedRoute> routes;

    private SceneDescription(List<SceneNode> roots, Map<String, SceneNode> defs,
                             List<ResolvedRoute> routes) {
        this.roots = List.copyOf(roots);
        this.defs = Collections.unmodifiableMap(defs);
        this.routes = List.copyOf(routes);
    }

    /** The top-level nodes, in file order. */
    public List<SceneNode> roots() {
        return roots;
    }

    /** DEF name to node; when a name is defined twice, the later node. */
    public Map<String, SceneNode> defs() {
        return defs;
    }

    /** The ROUTEs whose nodes this viewer animates, resolved and type-checked, in file order. */
    public List<ResolvedRoute> routes() {
        return routes;
    }

    /**
     * Collects DEF names, USEs and ROUTEs while a parser runs. A DEF name becomes usable once its
     * node is complete, so a node can never {@code USE} itself or an ancestor.
     */
    public static final class Collector {

        private static final Logger LOG = LoggerFactory.getLogger(SceneDescription.class);

        private final Map<String, SceneNode> defs = new HashMap<>();
        private final List<Route> routes = new ArrayList<>();
        private final ParseBudget budget;

        /** A collector that counts each {@code USE} against {@code budget}. */
        public Collector(ParseBudget budget) {
            this.budget = budget;
        }

        /** Makes {@code name} usable by later {@code USE}s and ROUTEs; a repeated name replaces the earlier node. */
        public void define(String name, SceneNode node) {
            defs.put(name, node);
        }

        /** The node a {@code USE} names, counted in full against the node limit. */
        public SceneNode use(String name, String where) throws ModelException {
            SceneNode node = defs.get(name);
            if (node == null) {
                throw new ModelException(Kind.UNKNOWN_NAME, where + ": USE '" + name
                        + "' names no node defined before it (DEF names become usable after"
                        + " their node ends)");
            }
            budget.addNodes(node.weight(), where + ": USE '" + name + "'");
            return node;
        }

        /** Keeps a ROUTE to resolve in {@link #finish}, once every DEF name is known. */
        public void route(Route route) {
            routes.add(route);
        }

        /** Resolves and type-checks the ROUTEs and returns the description; ROUTEs to unknown types are skipped. */
        public SceneDescription finish(List<SceneNode> roots) throws ModelException {
            List<ResolvedRoute> resolved = new ArrayList<>();
            for (Route route : routes) {
                SceneNode from = endpoint(route, route.fromNode());
                SceneNode to = endpoint(route, route.toNode());
                if (from.type().isEmpty() || to.type().isEmpty()) {
                    LOG.warn("{} ignored: {} is a node type this viewer does not animate",
                            route, from.type().isEmpty() ? from.label() : to.label());
                    continue;
                }
                FieldDef out = from.type().get().eventOut(route.fromField()).orElseThrow(
                        () -> new ModelException(Kind.UNKNOWN_NAME, route + ": " + from.label()
                                + " has no field '" + route.fromField() + "' that sends events"));
                FieldDef in = to.type().get().eventIn(route.toField()).orElseThrow(
                        () -> new ModelException(Kind.UNKNOWN_NAME, route + ": " + to.label()
                                + " has no field '" + route.toField()
                                + "' that receives events"));
                if (out.type() != in.type()) {
                    throw new ModelException(Kind.BAD_VALUE, route + ": " + route.fromField()
                            + " sends " + out.type() + " but " + route.toField() + " takes "
                            + in.type());
                }
                resolved.add(new ResolvedRoute(from, out, to, in));
            }
            return new SceneDescription(roots, new HashMap<>(defs), resolved);
        }

        private SceneNode endpoint(Route route, String name) throws ModelException {
            SceneNode node = defs.get(name);
            if (node == null) {
                throw new ModelException(Kind.UNKNOWN_NAME, route + ": no node is named '"
                        + name + "'");
            }
            return node;
        }
    }
}
