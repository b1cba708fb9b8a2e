package io.orchard.viewer.model.build;

import com.jme3.anim.AnimComposer;
import com.jme3.anim.AnimLayer;
import com.jme3.anim.Joint;
import com.jme3.anim.SkinningControl;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.Rig;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The rig of a glTF model or a placeholder, working on the spatials directly: joints are the
 * named nodes (and the joints of any skeleton), animations the clips of the
 * {@link AnimComposer}s found in the tree, and moves go to the node named after the agent, or to
 * the root.
 *
 * <p>The composers are kept disabled so that the scene's own update does not advance them; this
 * rig advances them by the simulated time {@link #update} receives, so one clock drives every
 * model.
 */
public final class SpatialRig implements Rig {

    private final Node root;
    private final Spatial agentNode;
    private final Map<String, Spatial> nodes = new LinkedHashMap<>();
    private final Map<String, Joint> joints = new LinkedHashMap<>();
    private final Set<String> spatialNames = new LinkedHashSet<>();
    private final List<AnimComposer> composers = new ArrayList<>();
    private MoveTween tween;

    /** Finds the named nodes, joints and animation composers under {@code root}, and disables the composers. */
    public SpatialRig(String agentName, Node root) {
        this.root = root;
        root.depthFirstTraversal(spatial -> {
            String name = spatial.getName();
            if (spatial != root && name != null) {
                spatialNames.add(name);
                if (spatial instanceof Node) {
                    nodes.putIfAbsent(name, spatial);
                }
            }
            AnimComposer composer = spatial.getControl(AnimComposer.class);
            if (composer != null) {
                composer.setEnabled(false);
                composers.add(composer);
            }
            SkinningControl skinning = spatial.getControl(SkinningControl.class);
            if (skinning != null) {
                for (Joint joint : skinning.getArmature().getJointList()) {
                    if (joint.getName() != null) {
                        joints.putIfAbsent(joint.getName(), joint);
                    }
                }
            }
        });
        this.agentNode = nodes.getOrDefault(agentName, root);
    }

    @Override
    public void moveTo(Vector3f from, Vector3f to, double startTime, double duration) {
        tween = new MoveTween(from, to, startTime, duration, agentNode::setLocalTranslation);
    }

    @Override
    public void setRotation(Quaternion rotation) {
        agentNode.setLocalRotation(rotation);
    }

    @Override
    public void setJointRotation(String joint, Quaternion rotation) throws ModelException {
        Spatial node = nodes.get(joint);
        if (node != null) {
            node.setLocalRotation(rotation);
            return;
        }
        Joint skeletal = joints.get(joint);
        if (skeletal == null) {
            throw UnknownName.error("joint (named node)", joint, jointNames());
        }
        skeletal.setLocalRotation(rotation);
    }

    @Override
    public void startAnimation(String name, boolean loop, double now) throws ModelException {
        for (AnimComposer composer : withClip(name)) {
            composer.setCurrentAction(name, AnimComposer.DEFAULT_LAYER, loop);
        }
    }

    @Override
    public void stopAnimation(String name) throws ModelException {
        for (AnimComposer composer : withClip(name)) {
            AnimLayer layer = composer.getLayer(AnimComposer.DEFAULT_LAYER);
            if (name.equals(layer.getCurrentActionName())) {
                composer.removeCurrentAction(AnimComposer.DEFAULT_LAYER);
            }
        }
    }

    private List<AnimComposer> withClip(String name) throws ModelException {
        List<AnimComposer> found = new ArrayList<>();
        for (AnimComposer composer : composers) {
            if (composer.hasAnimClip(name)) {
                found.add(composer);
            }
        }
        if (found.isEmpty()) {
            throw UnknownName.error("animation clip", name, animationNames());
        }
        return found;
    }

    @Override
    public boolean hasNode(String name) {
        return spatialNames.contains(name) || joints.containsKey(name);
    }

    @Override
    public Set<String> jointNames() {
        Set<String> names = new LinkedHashSet<>(nodes.keySet());
        names.addAll(joints.keySet());
        return Set.copyOf(names);
    }

    @Override
    public Set<String> timeSensorNames() {
        return Set.of();
    }

    @Override
    public Set<String> animationNames() {
        Set<String> names = new LinkedHashSet<>();
        for (AnimComposer composer : composers) {
            names.addAll(composer.getAnimClipsNames());
        }
        return Set.copyOf(names);
    }

    @Override
    public void update(double time, double elapsed) {
        if (elapsed > 0) {
            for (AnimComposer composer : composers) {
                composer.setEnabled(true);
                composer.update((float) elapsed);
                composer.setEnabled(false);
            }
        }
        if (tween != null) {
            tween.apply(time);
            if (tween.isDone()) {
                tween = null;
            }
        }
    }
}
