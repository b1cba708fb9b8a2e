package io.orchard.viewer.model;

import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import java.util.Set;

/**
 * How a {@link BodyModel} moves, poses and animates its spatials: through the event graph of
 * a VRML97 or X3D model, or directly on the spatials of a glTF model or a placeholder. The rigs
 * are in {@code io.orchard.viewer.model.build}; the rest of the viewer goes through
 * {@link BodyModel}, which checks the arguments (and documents each operation) before they
 * arrive here.
 */
public interface Rig {

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
}
