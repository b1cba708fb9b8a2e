package io.orchard.viewer.scene;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Box;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import java.util.List;

/**
 * The ground (the walkable rectangle, and meadow around it to the horizon), the river as a flat
 * band of water just above the ground, and the bridges: a wooden deck of the bridge's width from
 * entry to entry, with low railings.
 */
public final class Landscape {

    /** How high the water lies above the ground, so that it never fights the ground for depth. */
    public static final float WATER_LEVEL = 0.06f;
    /** How high a bridge's deck stands. */
    public static final float DECK_HEIGHT = 0.3f;

    private final Palette palette;

    /** Builds the ground, the river and the bridges in the colours of {@code palette}. */
    public Landscape(Palette palette) {
        this.palette = palette;
    }

    /** The walkable ground, and meadow reaching {@code margin} units beyond it on every side. */
    public Node ground(Bounds bounds, float margin) {
        Node ground = new Node("ground");
        float minX = (float) bounds.minX();
        float maxX = (float) bounds.maxX();
        float minZ = (float) bounds.minZ();
        float maxZ = (float) bounds.maxZ();
        ground.attachChild(slab("walkable ground", minX, minZ, maxX, maxZ, palette.lit(Palette.GRASS)));
        var meadow = palette.lit(Palette.MEADOW);
        ground.attachChild(slab("meadow north", minX - margin, minZ - margin, maxX + margin, minZ, meadow));
        ground.attachChild(slab("meadow south", minX - margin, maxZ, maxX + margin, maxZ + margin, meadow));
        ground.attachChild(slab("meadow west", minX - margin, minZ, minX, maxZ, meadow));
        ground.attachChild(slab("meadow east", maxX, minZ, maxX + margin, maxZ, meadow));
        ground.setShadowMode(ShadowMode.Receive);
        return ground;
    }

    /** The river's water. */
    public Geometry river(RiverShape river) {
        Geometry water = new Geometry("river", Meshes.polygon(river.outline(), WATER_LEVEL));
        water.setMaterial(palette.lit(Palette.WATER));
        water.setShadowMode(ShadowMode.Receive);
        return water;
    }

    /** A bridge: its deck from entry A to entry B, and a railing along each side. */
    public Node bridge(BridgeShape bridge) {
        Node node = new Node("bridge " + bridge.id());
        Point2 a = bridge.entryA();
        Point2 b = bridge.entryB();
        float dx = (float) (b.x() - a.x());
        float dz = (float) (b.z() - a.z());
        float length = FastMath.sqrt(dx * dx + dz * dz);
        float half = (float) bridge.width() / 2;
        Geometry deck = new Geometry("deck " + bridge.id(), new Box(half, DECK_HEIGHT / 2, length / 2 + 0.3f));
        deck.setMaterial(palette.lit(Palette.WOOD));
        deck.setLocalTranslation(0, DECK_HEIGHT / 2, 0);
        node.attachChild(deck);
        for (int side = -1; side <= 1; side += 2) {
            Geometry rail = new Geometry("railing " + bridge.id(), new Box(0.06f, 0.35f, length / 2 + 0.3f));
            rail.setMaterial(palette.lit(Palette.BARK));
            rail.setLocalTranslation(side * (half - 0.06f), DECK_HEIGHT + 0.35f, 0);
            node.attachChild(rail);
        }
        node.setLocalTranslation((float) (a.x() + b.x()) / 2, 0, (float) (a.z() + b.z()) / 2);
        // The boxes are long along z; turn z onto the direction from A to B.
        node.rotate(0, FastMath.atan2(dx, dz), 0);
        node.setShadowMode(ShadowMode.CastAndReceive);
        return node;
    }

    private static Geometry slab(String name, float x0, float z0, float x1, float z1, com.jme3.material.Material material) {
        List<Point2> corners = List.of(new Point2(x0, z0), new Point2(x1, z0), new Point2(x1, z1), new Point2(x0, z1));
        Geometry geometry = new Geometry(name, Meshes.polygon(corners, 0));
        geometry.setMaterial(material);
        return geometry;
    }

    /** The centre of the walkable ground, on the ground. */
    public static Vector3f centre(Bounds bounds) {
        return new Vector3f((float) (bounds.minX() + bounds.maxX()) / 2, 0, (float) (bounds.minZ() + bounds.maxZ()) / 2);
    }
}
