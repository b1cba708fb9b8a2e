package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.shadow.DirectionalLightShadowRenderer;
import com.jme3.shadow.EdgeFilteringMode;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.viewer.scene.Castles;
import io.orchard.viewer.scene.Fruits;
import io.orchard.viewer.scene.Landscape;
import io.orchard.viewer.scene.Meshes;
import io.orchard.viewer.scene.Palette;
import io.orchard.viewer.scene.Sky;
import io.orchard.viewer.scene.Tables;
import io.orchard.viewer.scene.Trees;
import io.orchard.viewer.world.WorldMirror;
import java.util.HashMap;
import java.util.Map;
import jme3tools.optimize.GeometryBatchFactory;

/**
 * The world that does not walk: lights, shadows and sky, and from each snapshot the ground, the
 * river and bridges, the castle, trees and tables (batched into a few draw calls, since they never
 * change), and the fruit, each its own node so that it can vanish when eaten.
 *
 * <p>Shadow maps cost the software renderer four to six times its frame rate, so they are
 * optional ({@link #setShadows}); without them, flat shades on the ground under the crowns and
 * tables, cast away from the sun, stand in for shadows at no cost.
 */
public final class WorldSceneState extends BaseAppState implements WorldMirror.Listener {

    /** The sun's direction: from the south-east and high. */
    public static final Vector3f SUN = new Vector3f(-0.45f, -1f, -0.35f).normalizeLocal();

    private final WorldMirror mirror;
    private boolean shadows;
    private final Node world = new Node("world");
    private final Node fruitNode = new Node("fruit");
    private Node shades = new Node("shades");
    private final Map<String, Node> fruit = new HashMap<>();
    private Palette palette;
    private DirectionalLight sun;
    private AmbientLight ambient;
    private DirectionalLightShadowRenderer shadowRenderer;
    private Node root;

    /** The world of {@code mirror}'s snapshots, with shadows when {@code shadows} is set. */
    public WorldSceneState(WorldMirror mirror, boolean shadows) {
        this.mirror = mirror;
        this.shadows = shadows;
    }

    @Override
    protected void initialize(Application app) {
        palette = new Palette(app.getAssetManager());
        root = ((SimpleApplication) app).getRootNode();
        sun = new DirectionalLight(SUN, ColorRGBA.White.mult(1.1f));
        ambient = new AmbientLight(ColorRGBA.White.mult(0.55f));
        root.addLight(sun);
        root.addLight(ambient);
        app.getViewPort().setBackgroundColor(Sky.HORIZON);
        root.attachChild(Sky.build(app.getAssetManager(), app.getCamera()));
        // The cheapest shadows that still look right: one 1024 map, bilinear edges.
        shadowRenderer = new DirectionalLightShadowRenderer(app.getAssetManager(), 1024, 1);
        shadowRenderer.setLight(sun);
        shadowRenderer.setShadowIntensity(0.45f);
        shadowRenderer.setEdgeFilteringMode(EdgeFilteringMode.Bilinear);
        setShadows(shadows);
        world.attachChild(fruitNode);
        root.attachChild(world);
        mirror.addListener(this);
        mirror.snapshot().ifPresent(this::worldShown);
    }

    @Override
    public void worldShown(WorldSnapshotMessage snapshot) {
        worldCleared();
        Landscape landscape = new Landscape(palette);
        float size = (float) Math.max(snapshot.bounds().maxX() - snapshot.bounds().minX(),
                snapshot.bounds().maxZ() - snapshot.bounds().minZ());
        Node flat = new Node("flat");
        flat.attachChild(landscape.ground(snapshot.bounds(), Math.max(2000, size * 10)));
        flat.attachChild(landscape.river(snapshot.river()));
        flat.setShadowMode(ShadowMode.Receive);
        Node solid = new Node("solid");
        snapshot.bridges().forEach(bridge -> solid.attachChild(landscape.bridge(bridge)));
        solid.attachChild(new Castles(palette).build(snapshot.castle()));
        Trees trees = new Trees(palette);
        Tables tables = new Tables(palette);
        for (Obstacle obstacle : snapshot.obstacles()) {
            solid.attachChild(obstacle.kind() == ObjectKind.TREE ? trees.build(obstacle) : tables.build(obstacle));
        }
        // One draw call per material instead of one per part: the software renderer pays per call.
        GeometryBatchFactory.optimize(solid);
        solid.setShadowMode(ShadowMode.CastAndReceive);
        shades = shades(snapshot);
        world.attachChildAt(flat, 0);
        world.attachChildAt(solid, 1);
        world.attachChildAt(shades, 2);
        Map<String, Obstacle> supports = new HashMap<>();
        snapshot.obstacles().forEach(o -> supports.put(o.id(), o));
        Fruits fruits = new Fruits(palette);
        for (FruitState state : mirror.fruit()) {
            Obstacle support = state.support() == null ? null : supports.get(state.support());
            float stalk = support != null && support.kind() == ObjectKind.TREE
                    ? Trees.crownBottom(support) - (float) state.position().y() + 0.2f : 0;
            Node node = fruits.build(state, stalk);
            fruit.put(state.id(), node);
            fruitNode.attachChild(node);
        }
    }

    /** Flat shades on the ground, cast away from the sun, under every crown and table top. */
    private Node shades(WorldSnapshotMessage snapshot) {
        Node node = new Node("shades");
        for (Obstacle obstacle : snapshot.obstacles()) {
            float high = obstacle.kind() == ObjectKind.TREE
                    ? (Trees.crownBottom(obstacle) + (float) obstacle.height()) / 2 : (float) obstacle.height();
            float reach = high / -SUN.y;
            Geometry shade = new Geometry("shade " + obstacle.id(), Meshes.ring(0, (float) obstacle.radius(), 20));
            shade.setMaterial(palette.lit(Palette.SHADE));
            shade.setLocalTranslation((float) obstacle.position().x() + SUN.x * reach, 0.02f,
                    (float) obstacle.position().z() + SUN.z * reach);
            node.attachChild(shade);
        }
        GeometryBatchFactory.optimize(node);
        node.setShadowMode(ShadowMode.Off);
        node.setCullHint(shadows ? Node.CullHint.Always : Node.CullHint.Inherit);
        return node;
    }

    /** Draws shadow maps, or the flat shades that stand in for them. */
    public void setShadows(boolean on) {
        shadows = on;
        var viewPort = getApplication().getViewPort();
        if (on && !viewPort.getProcessors().contains(shadowRenderer)) {
            viewPort.addProcessor(shadowRenderer);
        } else if (!on) {
            viewPort.removeProcessor(shadowRenderer);
        }
        shades.setCullHint(on ? Node.CullHint.Always : Node.CullHint.Inherit);
    }

    @Override
    public void worldCleared() {
        world.detachAllChildren();
        fruitNode.detachAllChildren();
        fruit.clear();
        world.attachChild(fruitNode);
    }

    @Override
    public void fruitRemoved(FruitState gone, String eatenBy) {
        Node node = fruit.remove(gone.id());
        if (node != null) {
            node.removeFromParent();
        }
    }

    /** The node of a fruit still shown, or null. */
    public Node fruitNode(String id) {
        return fruit.get(id);
    }

    /** Whether shadow maps are drawn (otherwise flat shades stand in). */
    public boolean hasShadows() {
        return shadows;
    }

    @Override
    protected void cleanup(Application app) {
        mirror.removeListener(this);
        world.removeFromParent();
        root.removeLight(sun);
        root.removeLight(ambient);
        app.getViewPort().removeProcessor(shadowRenderer);
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
