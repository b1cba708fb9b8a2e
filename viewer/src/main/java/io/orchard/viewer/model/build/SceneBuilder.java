package io.orchard.viewer.model.build;

import com.jme3.asset.AssetManager;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.SceneDescription;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.event.EventGraph;
import io.orchard.viewer.model.event.LiveInterpolator;
import io.orchard.viewer.model.event.LiveNode;
import io.orchard.viewer.model.event.LiveTimeSensor;
import io.orchard.viewer.model.event.LiveTransform;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Builds jME spatials and the event graph from a {@link SceneDescription}.
 *
 * <p>Grouping nodes become {@link Node}s and shapes {@link Geometry}s, each named after its DEF
 * name (or its type when it has none), so a joint such as {@code LeftKnee} is found with
 * {@code getChild("LeftKnee")}. A node used in several places ({@code USE}) appears as several
 * spatials, since a jME spatial has one parent; they share their mesh and, through the live
 * node, their state: moving a USEd Transform moves every copy.
 *
 * <p>TimeSensors, interpolators, and every Transform and Material a ROUTE reaches become live
 * nodes of the {@link EventGraph}.
 */
public final class SceneBuilder {

    private static final Logger LOG = LoggerFactory.getLogger(SceneBuilder.class);
    private static final Set<String> GROUPS =
            Set.of("Group", "Collision", "Anchor", "Billboard");
    /** Nodes about the world or the camera, not the agent's body: skipped without a warning. */
    private static final Set<String> ENVIRONMENT = Set.of("WorldInfo", "Viewpoint",
            "NavigationInfo", "Background", "Fog", "DirectionalLight", "PointLight",
            "SpotLight", "Sound", "AudioClip");

    /** What a built model is made of. */
    public record Result(Node root, EventGraph graph, Map<String, LiveTransform> transforms,
                         Map<String, LiveTimeSensor> sensors,
                         Map<String, LiveInterpolator> interpolators, Set<String> defNames) {
    }

    private final Appearances appearances;
    private final Map<SceneNode, LiveTransform> transforms = new IdentityHashMap<>();
    private final Map<SceneNode, FaceSets.Built> meshes = new IdentityHashMap<>();
    private final Set<SceneNode> meshless = Collections.newSetFromMap(new IdentityHashMap<>());
    private final Set<String> warned = new HashSet<>();

    private SceneBuilder(AssetManager assets, ModelLimits limits) {
        this.appearances = new Appearances(assets, limits);
    }

    /** Builds the spatials, under a root named {@code rootName}, and the event graph of {@code scene}. */
    public static Result build(SceneDescription scene, String rootName, AssetManager assets,
                               ModelLimits limits) throws ModelException {
        return new SceneBuilder(assets, limits).run(scene, rootName);
    }

    private Result run(SceneDescription scene, String rootName) throws ModelException {
        Node root = new Node(rootName);
        for (SceneNode node : scene.roots()) {
            Spatial spatial = spatial(node);
            if (spatial != null) {
                root.attachChild(spatial);
            }
        }
        Map<SceneNode, LiveNode> live = new IdentityHashMap<>();
        Map<String, LiveTimeSensor> sensors = new LinkedHashMap<>();
        Map<String, LiveInterpolator> interpolators = new LinkedHashMap<>();
        EventGraph graph = new EventGraph();
        for (SceneNode node : allNodes(scene)) {
            LiveNode liveNode = switch (node.typeName()) {
                case "TimeSensor" -> {
                    LiveTimeSensor sensor = LiveTimeSensor.of(node);
                    graph.addSensor(sensor);
                    yield sensor;
                }
                case "PositionInterpolator", "OrientationInterpolator", "ScalarInterpolator" ->
                        LiveInterpolator.of(node);
                case "Transform" -> transforms.computeIfAbsent(node, LiveTransform::new);
                case "Material" -> appearances.live(node);
                default -> null;
            };
            if (liveNode != null) {
                live.put(node, liveNode);
            }
        }
        for (SceneDescription.ResolvedRoute route : scene.routes()) {
            LiveNode from = live.get(route.from());
            LiveNode to = live.get(route.to());
            if (from == null || to == null) {
                LOG.warn("ROUTE from {}.{} to {}.{} has no effect in this viewer",
                        route.from().label(), route.fromField().name(), route.to().label(),
                        route.toField().name());
                continue;
            }
            graph.addRoute(from, route.fromField().name(), to, route.toField().name());
        }
        // By DEF name; a name defined twice means its later node, as for USE.
        Map<String, LiveTransform> namedTransforms = new LinkedHashMap<>();
        scene.defs().forEach((name, node) -> {
            LiveNode liveNode = live.get(node);
            if (liveNode instanceof LiveTransform transform) {
                namedTransforms.put(name, transform);
            } else if (liveNode instanceof LiveTimeSensor sensor) {
                sensors.put(name, sensor);
            } else if (liveNode instanceof LiveInterpolator interpolator) {
                interpolators.put(name, interpolator);
            }
        });
        return new Result(root, graph, namedTransforms, sensors, interpolators,
                Set.copyOf(scene.defs().keySet()));
    }

    /** The spatial for a child node, or null for nodes that show nothing. */
    private Spatial spatial(SceneNode node) throws ModelException {
        String type = node.typeName();
        if (!node.isKnown()) {
            if (type.startsWith("Metadata")) {
                LOG.debug("{}: {} is not part of an agent's body; skipped", node.location(), type);
            } else if (ENVIRONMENT.contains(type)) {
                if (warned.add(type)) {
                    LOG.info("{}: {} belongs to a world, not to an agent's body; it is not shown",
                            node.location(), type);
                }
            } else if (warned.add(type)) {
                LOG.warn("{}: node type {} is not supported; it and its children are not shown",
                        node.location(), type);
            }
            return null;
        }
        if (type.equals("Transform")) {
            Node transform = transforms.computeIfAbsent(node, LiveTransform::new).newInstance();
            attachAll(transform, node.nodes("children"));
            return transform;
        }
        if (GROUPS.contains(type)) {
            Node group = new Node(name(node));
            attachAll(group, node.nodes("children"));
            return group;
        }
        if (type.equals("Switch")) {
            List<SceneNode> choices = node.has("choice") ? node.nodes("choice")
                    : node.nodes("children");
            return chosen(node, choices, node.integer("whichChoice"));
        }
        if (type.equals("LOD")) {
            List<SceneNode> levels = node.has("level") ? node.nodes("level")
                    : node.nodes("children");
            return chosen(node, levels, 0);
        }
        if (type.equals("Shape")) {
            return shape(node);
        }
        return null;
    }

    private Node chosen(SceneNode node, List<SceneNode> choices, int which)
            throws ModelException {
        Node group = new Node(name(node));
        if (which >= 0 && which < choices.size()) {
            Spatial spatial = spatial(choices.get(which));
            if (spatial != null) {
                group.attachChild(spatial);
            }
        }
        return group;
    }

    private void attachAll(Node parent, List<SceneNode> children) throws ModelException {
        for (SceneNode child : children) {
            Spatial spatial = spatial(child);
            if (spatial != null) {
                parent.attachChild(spatial);
            }
        }
    }

    private Spatial shape(SceneNode shape) throws ModelException {
        SceneNode geometryNode = shape.node("geometry");
        if (geometryNode == null) {
            return null;
        }
        FaceSets.Built built = mesh(geometryNode);
        if (built == null) {
            return null;
        }
        String name = shape.defName().or(geometryNode::defName)
                .orElse(geometryNode.typeName());
        Geometry geometry = new Geometry(name, built.mesh());
        appearances.apply(geometry, shape.node("appearance", "Appearance"), built);
        return geometry;
    }

    private FaceSets.Built mesh(SceneNode node) throws ModelException {
        FaceSets.Built built = meshes.get(node);
        if (built != null || meshless.contains(node)) {
            return built;
        }
        built = switch (node.typeName()) {
            case "Box" -> {
                float[] size = node.floats("size");
                positive(node, "size", size);
                yield solid(Primitives.box(size[0], size[1], size[2]));
            }
            case "Sphere" -> solid(Primitives.sphere(positive(node, "radius")));
            case "Cylinder" -> solid(Primitives.cylinder(positive(node, "radius"),
                    positive(node, "height"), node.bool("side"), node.bool("top"),
                    node.bool("bottom")));
            case "Cone" -> solid(Primitives.cone(positive(node, "bottomRadius"),
                    positive(node, "height"), node.bool("side"), node.bool("bottom")));
            case "IndexedFaceSet" -> FaceSets.faceSet(node, true);
            case "IndexedLineSet" -> FaceSets.lineSet(node);
            default -> {
                if (warned.add(node.typeName())) {
                    LOG.warn("{}: geometry type {} is not supported; the shape is not shown",
                            node.location(), node.typeName());
                }
                yield null;
            }
        };
        if (built == null) {
            meshless.add(node);
        } else {
            meshes.put(node, built);
        }
        return built;
    }

    private static FaceSets.Built solid(Mesh mesh) {
        return new FaceSets.Built(mesh, false, false, true);
    }

    private static float positive(SceneNode node, String field) throws ModelException {
        double value = node.number(field);
        if (!(value > 0)) {
            throw new ModelException(Kind.BAD_VALUE, node.location() + ": " + node.label()
                    + " field " + field + " must be positive but is " + value);
        }
        return (float) value;
    }

    private static void positive(SceneNode node, String field, float[] values)
            throws ModelException {
        for (float value : values) {
            if (!(value > 0)) {
                throw new ModelException(Kind.BAD_VALUE, node.location() + ": " + node.label()
                        + " field " + field + " must be positive in every component but is "
                        + values[0] + " " + values[1] + " " + values[2]);
            }
        }
    }

    /** Every node in the description once, USEs included once, without recursion. */
    private static List<SceneNode> allNodes(SceneDescription scene) {
        Set<SceneNode> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        List<SceneNode> ordered = new ArrayList<>();
        Deque<SceneNode> pending = new ArrayDeque<>(scene.roots());
        pending.addAll(scene.defs().values());
        while (!pending.isEmpty()) {
            SceneNode node = pending.removeFirst();
            if (seen.add(node)) {
                ordered.add(node);
                List<SceneNode> children = node.childNodes();
                for (int i = children.size() - 1; i >= 0; i--) {
                    pending.addFirst(children.get(i));
                }
            }
        }
        return ordered;
    }

    private static String name(SceneNode node) {
        return node.defName().orElse(node.typeName());
    }
}
