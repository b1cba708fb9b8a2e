package io.orchard.viewer.scene;

import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Sphere;
import io.orchard.protocol.value.Obstacle;

/**
 * A tree drawn from its bounding cylinder: a trunk of the radius the server blocks agents with
 * (15 % of the crown's radius, between 0.2 and 0.5), and a crown that fills the cylinder's upper
 * part, high enough for fruit to hang beneath it (fruit hangs up to 3 units high).
 */
public final class Trees {

    /** The crown's underside is never lower than this, so that hanging fruit shows beneath it. */
    static final float LOWEST_CROWN = 3.3f;

    private final Palette palette;

    /** Builds trees in the colours of {@code palette}. */
    public Trees(Palette palette) {
        this.palette = palette;
    }

    /** The radius of a tree's trunk, as the server models it. */
    public static float trunkRadius(Obstacle tree) {
        float crown = (float) tree.radius();
        return Math.min(crown, Math.max(0.2f, Math.min(0.5f, 0.15f * crown)));
    }

    /** The height of the underside of a tree's crown. */
    public static float crownBottom(Obstacle tree) {
        float height = (float) tree.height();
        return Math.min(Math.max(LOWEST_CROWN, 0.45f * height), height - 0.6f);
    }

    /** The tree's node, standing at its position. */
    public Node build(Obstacle tree) {
        Node node = new Node("tree " + tree.id());
        float height = (float) tree.height();
        float bottom = crownBottom(tree);
        float trunkTop = bottom + 0.35f * (height - bottom);
        Geometry trunk = new Geometry("trunk " + tree.id(), Meshes.cylinder(trunkRadius(tree),
                trunkRadius(tree) * 0.7f, trunkTop, 10));
        trunk.setMaterial(palette.lit(Palette.BARK));
        node.attachChild(trunk);
        float halfHeight = (height - bottom) / 2;
        Geometry crown = new Geometry("crown " + tree.id(), new Sphere(10, 14, 1f));
        crown.setMaterial(palette.lit(Palette.LEAVES));
        crown.setLocalScale((float) tree.radius(), halfHeight, (float) tree.radius());
        crown.setLocalTranslation(0, bottom + halfHeight, 0);
        node.attachChild(crown);
        node.setLocalTranslation((float) tree.position().x(), 0, (float) tree.position().z());
        node.setShadowMode(ShadowMode.CastAndReceive);
        return node;
    }
}
