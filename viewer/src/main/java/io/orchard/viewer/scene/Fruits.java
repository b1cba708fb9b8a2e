package io.orchard.viewer.scene;

import com.jme3.math.FastMath;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Sphere;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;

/**
 * Fruit, each with its kind's look at its position: a red tomato with a green calyx, a yellow
 * curved banana, a brown coconut; each fills the sphere the server models it by. Fruit hanging in
 * a tree gets a stalk up to the crown.
 */
public final class Fruits {

    private final Palette palette;

    /** Builds fruit in the colours of {@code palette}. */
    public Fruits(Palette palette) {
        this.palette = palette;
    }

    /**
     * The fruit's node, named after its id, centred on its position.
     *
     * @param stalk how far up a stalk reaches from the fruit's centre, 0 for none
     */
    public Node build(FruitState fruit, float stalk) {
        Node node = new Node(fruit.id());
        float radius = (float) fruit.kind().radius();
        if (fruit.kind() == FruitKind.TOMATO) {
            Geometry body = new Geometry("tomato " + fruit.id(), new Sphere(12, 16, radius));
            body.setLocalScale(1, 0.85f, 1);
            body.setMaterial(palette.lit(Palette.TOMATO));
            node.attachChild(body);
            Geometry calyx = new Geometry("calyx " + fruit.id(), Meshes.cylinder(radius * 0.45f, 0, radius * 0.3f, 6));
            calyx.setLocalTranslation(0, radius * 0.8f, 0);
            calyx.setMaterial(palette.lit(Palette.STALK));
            node.attachChild(calyx);
        } else if (fruit.kind() == FruitKind.BANANA) {
            // An arc of 2.2 radians of radius 0.3 spans about 0.53, the sphere's diameter.
            Geometry body = new Geometry("banana " + fruit.id(), Meshes.curvedTube(radius * 1.2f, 2.2f, radius * 0.3f, 12, 8));
            body.setMaterial(palette.lit(Palette.BANANA));
            body.setLocalTranslation(0, -radius * 0.7f, 0); // its underside touches the sphere's bottom
            // Turn each banana its own way, from its id, so that a bunch does not look stamped.
            body.rotate(0, (fruit.id().hashCode() & 0xff) / 255f * FastMath.TWO_PI, 0);
            node.attachChild(body);
        } else {
            Geometry body = new Geometry("coconut " + fruit.id(), new Sphere(12, 16, radius));
            body.setLocalScale(1, 1.08f, 1);
            body.setMaterial(palette.lit(Palette.COCONUT));
            node.attachChild(body);
        }
        if (stalk > radius) {
            Geometry stem = new Geometry("stalk " + fruit.id(), Meshes.cylinder(0.02f, 0.02f, stalk - radius * 0.8f, 4));
            stem.setLocalTranslation(0, radius * 0.8f, 0);
            stem.setMaterial(palette.lit(Palette.STALK));
            node.attachChild(stem);
        }
        node.setLocalTranslation((float) fruit.position().x(), (float) fruit.position().y(), (float) fruit.position().z());
        node.setShadowMode(ShadowMode.CastAndReceive);
        return node;
    }
}
