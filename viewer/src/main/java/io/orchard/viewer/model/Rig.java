package io.orchard.viewer.model;

import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import java.util.Set;

/**
 * How an {@link AgentModel} moves, poses and animates its spatials: through the event graph of
 * a VRML97 or X3D model, or directly on the spatials of a glTF model or a placeholder. Arguments
 * arrive checked.
 */
interface Rig {

    void moveTo(Vector3f from, Vector3f to, double startTime, double duration);

    void setRotation(Quaternion rotation);

    void setJointRotation(String joint, Quaternion rotation) throws ModelException;

    void startAnimation(String name, boolean loop, double now) throws ModelException;

    void stopAnimation(String name) throws ModelException;

    boolean hasNode(String name);

    Set<String> jointNames();

    Set<String> timeSensorNames();

    Set<String> animationNames();

    /** Advances to simulated time {@code time}, {@code elapsed} seconds after the last call. */
    void update(double time, double elapsed);

    static ModelException unknown(String what, String name, Set<String> known) {
        String list = known.stream().sorted().limit(20).toList()
                + (known.size() > 20 ? " and " + (known.size() - 20) + " more" : "");
        return new ModelException(ModelException.Kind.UNKNOWN_NAME, "the model has no " + what
                + " named '" + name + "'; it has " + (known.isEmpty() ? "none" : list));
    }
}
