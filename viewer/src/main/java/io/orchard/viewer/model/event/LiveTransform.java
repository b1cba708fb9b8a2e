package io.orchard.viewer.model.event;

import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import io.orchard.viewer.model.Rotations;
import io.orchard.viewer.model.SceneNode;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A VRML Transform at run time, and the jME nodes that show it: one per place the Transform
 * appears (a {@code USE} adds a place), all kept equal.
 *
 * <p>VRML composes {@code T·C·R·SR·S·SR⁻¹·C⁻¹}; a jME node holds a translation, a rotation and
 * a scale applied along its own axes. The centre folds exactly into the translation
 * ({@code T + C - R·(S·C)}). A scale orientation cannot be shown: jME composes transforms
 * without shear, so a non-uniform scale is always applied along the node's own axes. It is
 * ignored with a warning; the same holds for a non-uniform scale above rotated children.
 */
public final class LiveTransform implements LiveNode {

    private static final Logger LOG = LoggerFactory.getLogger(LiveTransform.class);

    private final String name;
    private final List<Node> instances = new ArrayList<>();
    private final Vector3f translation;
    private final Vector3f scale;
    private final Vector3f center;
    private Quaternion rotation;
    private boolean warnedScaleOrientation;

    /** The Transform the node {@code source} describes, not yet shown by any jME node. */
    public LiveTransform(SceneNode source) {
        this.name = source.defName().orElse("Transform");
        this.translation = vector(source.floats("translation"));
        this.scale = vector(source.floats("scale"));
        this.center = vector(source.floats("center"));
        this.rotation = Rotations.fromAxisAngle(source.floats("rotation"), 0);
        checkScaleOrientation(source.floats("scaleOrientation"));
    }

    @Override
    public String toString() {
        return "Transform '" + name + "'";
    }

    /** Creates the node for one more place the Transform appears. */
    public Node newInstance() {
        Node node = new Node(name);
        instances.add(node);
        apply(node);
        return node;
    }

    /** Sets the translation of every instance, without sending an event. */
    public void setTranslation(Vector3f value) {
        translation.set(value);
        applyAll();
    }

    /** Sets the rotation of every instance, without sending an event. */
    public void setRotation(Quaternion value) {
        rotation = value.clone();
        applyAll();
    }

    @Override
    public void receive(String field, Object value, EventGraph.Cascade cascade) {
        float[] v = (float[]) value;
        switch (field) {
            case "translation" -> translation.set(v[0], v[1], v[2]);
            case "scale" -> scale.set(v[0], v[1], v[2]);
            case "center" -> center.set(v[0], v[1], v[2]);
            case "rotation" -> rotation = Rotations.fromAxisAngle(v, 0);
            case "scaleOrientation" -> checkScaleOrientation(v);
            default -> {
                return;
            }
        }
        applyAll();
        cascade.emit(this, field, value);
    }

    private void applyAll() {
        for (Node node : instances) {
            apply(node);
        }
    }

    private void apply(Node node) {
        Vector3f scaledCenter = center.mult(scale);
        Vector3f shift = center.subtract(rotation.mult(scaledCenter));
        node.setLocalTranslation(translation.add(shift));
        node.setLocalRotation(rotation);
        node.setLocalScale(scale);
    }

    private void checkScaleOrientation(float[] value) {
        boolean uniform = scale.x == scale.y && scale.y == scale.z;
        if (!uniform && !Rotations.fromAxisAngle(value, 0).isIdentity()
                && !warnedScaleOrientation) {
            warnedScaleOrientation = true;
            LOG.warn("Transform '{}': scaleOrientation is not supported; its scale applies"
                    + " along the Transform's own axes", name);
        }
    }

    private static Vector3f vector(float[] v) {
        return new Vector3f(v[0], v[1], v[2]);
    }
}
