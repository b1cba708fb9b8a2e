package io.orchard.viewer.model;

import com.jme3.bounding.BoundingBox;
import com.jme3.bounding.BoundingVolume;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.util.List;

/**
 * Scales a model to its agent's body height and stands it on the ground at the body's centre:
 * everything under the node that moves (the one named after the agent, or the root) goes into a
 * node of its own, scaled and shifted so that the model's bounds, as authored, run from y = 0 to
 * the height and are centred on x = z = 0. The moving node keeps its own transform, so moves and
 * turns stay in the world's metres. Models are authored in centimetres, with the origin at a
 * corner or the centre of mass, and as tall as a house; the paper's agents share one world and
 * one scale.
 */
final class Fitting {

    private Fitting() {
    }

    /** Fits {@code model} to {@code height} metres; a model with no extent is left as it is. */
    static void fit(Node root, String agentName, float height) {
        Node moving = movingNode(root, agentName);
        Node fitted = new Node(agentName + " fitted");
        for (Spatial child : List.copyOf(moving.getChildren())) {
            fitted.attachChild(child);
        }
        // Bounds in the moving node's own frame: measured with the fitted node alone, at identity.
        fitted.updateGeometricState();
        BoundingVolume bound = fitted.getWorldBound();
        moving.attachChild(fitted);
        if (!(bound instanceof BoundingBox box) || !Vector3f.isValidVector(box.getCenter())) {
            return;
        }
        float tall = box.getYExtent() * 2;
        if (!(tall > 0) || !Float.isFinite(tall)) {
            return;
        }
        // The moving node's own scale (an export's centimetres, often) stays; the fitted node undoes it.
        float own = moving.getLocalScale().y;
        float scale = height / (tall * (own > 0 ? own : 1));
        Vector3f centre = box.getCenter();
        fitted.setLocalScale(scale);
        fitted.setLocalTranslation(-centre.x * scale, -(centre.y - box.getYExtent()) * scale, -centre.z * scale);
    }

    /** The node moves go to, found as {@code SpatialRig} finds it: the first named after the agent, depth first. */
    private static Node movingNode(Node root, String agentName) {
        Node[] found = new Node[1];
        root.depthFirstTraversal(spatial -> {
            if (found[0] == null && spatial != root && spatial instanceof Node node
                    && agentName.equals(spatial.getName())) {
                found[0] = node;
            }
        });
        return found[0] != null ? found[0] : root;
    }
}
