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

    /** Moves the agent from {@code from} to {@code to} over {@code duration} seconds from {@code startTime}. */
    void moveTo(Vector3f from, Vector3f to, double startTime, double duration);

    /** Sets the rotation of the whole agent. */
    void setRotation(Quaternion rotation);

    /** Sets the rotation of the named joint, or throws if the model has no such joint. */
    void setJointRotation(String joint, Quaternion rotation) throws ModelException;

    /** Starts the named animation at time {@code now}, looping or once. */
    void startAnimation(String name, boolean loop, double now) throws ModelException;

    /** Stops the named animation, leaving the pose where it is. */
    void stopAnimation(String name) throws ModelException;

    /** Whether the model has a node of that name: a DEF name, or a glTF node or joint name. */
    boolean hasNode(String name);

    /** The names {@link #setJointRotation} accepts. */
    Set<String> jointNames();

    /** The DEF names of the model's TimeSensors (empty for glTF). */
    Set<String> timeSensorNames();

    /** The names {@link #startAnimation} accepts. */
    Set<String> animationNames();

    /** Advances to simulated time {@code time}, {@code elapsed} seconds after the last call. */
    void update(double time, double elapsed);
}
