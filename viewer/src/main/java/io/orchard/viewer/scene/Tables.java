package io.orchard.viewer.scene;

import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import io.orchard.protocol.value.Obstacle;

/** A round table drawn from its cylinder: a top of its radius at its height, on a pedestal and a foot. */
public final class Tables {

    private static final float TOP_THICKNESS = 0.07f;

    private final Palette palette;

    /** Builds tables in the colours of {@code palette}. */
    public Tables(Palette palette) {
        this.palette = palette;
    }

    /** The table's node, standing at its position. */
    public Node build(Obstacle table) {
        Node node = new Node("table " + table.id());
        float radius = (float) table.radius();
        float height = (float) table.height();
        Geometry top = new Geometry("table top " + table.id(), Meshes.cylinder(radius, radius, TOP_THICKNESS, 20));
        top.setMaterial(palette.lit(Palette.WOOD));
        top.setLocalTranslation(0, height - TOP_THICKNESS, 0);
        node.attachChild(top);
        Geometry leg = new Geometry("table leg " + table.id(), Meshes.cylinder(0.07f, 0.07f, height - TOP_THICKNESS, 8));
        leg.setMaterial(palette.lit(Palette.BARK));
        node.attachChild(leg);
        Geometry foot = new Geometry("table foot " + table.id(), Meshes.cylinder(radius * 0.5f, radius * 0.35f, 0.05f, 12));
        foot.setMaterial(palette.lit(Palette.BARK));
        node.attachChild(foot);
        node.setLocalTranslation((float) table.position().x(), 0, (float) table.position().z());
        node.setShadowMode(ShadowMode.CastAndReceive);
        return node;
    }
}
