package io.orchard.viewer.model;

import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.ModelException.Kind;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * One agent's body in the viewer, whatever format it came in: what the paper's applet reached
 * through the External Authoring Interface. The viewer attaches {@link #root()} to its scene and
 * turns the protocol's messages into calls here: {@code MoveMessage} into {@link #moveTo},
 * {@code SetRotationMessage} into {@link #setRotation}, {@code SetJointRotationMessage} into
 * {@link #setJointRotation}, {@code StartAnimationMessage} and {@code StopAnimationMessage} into
 * {@link #startAnimation} and {@link #stopAnimation}; registration messages can be checked with
 * {@link #hasNode}, {@link #jointNames()} and {@link #timeSensorNames()}.
 *
 * <p>Time is simulated and injected: {@link #update(double)} is given the current simulated time
 * each frame and advances TimeSensors, interpolators, glTF clips and moves to it, so a test (or a
 * fixed-step screenshot run) is deterministic. Times passed to {@link #moveTo} are on the same
 * clock.
 *
 * <p>Not thread-safe: like the jME scene it belongs to, it is used from the render thread only.
 * Each call driven by a message throws only {@link ModelException}, naming what was wrong, so a
 * bad message from one client never stops the viewer.
 */
public final class BodyModel {

    private final String agentName;
    private final ModelFormat format;
    private final Node root;
    private final Rig rig;
    private double now = Double.NEGATIVE_INFINITY;

    BodyModel(String agentName, ModelFormat format, Node root, Rig rig) {
        this.agentName = agentName;
        this.format = format;
        this.root = root;
        this.rig = rig;
    }

    /** The name the agent registered with; its Transform or node of that name moves. */
    public String agentName() {
        return agentName;
    }

    /** The format the model was loaded from; empty for a placeholder. */
    public Optional<ModelFormat> format() {
        return Optional.ofNullable(format);
    }

    /** Whether this is a stand-in for a model that could not be loaded. */
    public boolean isPlaceholder() {
        return format == null;
    }

    /**
     * The model's root node, named {@code "<agentName> model"}, to attach to the scene. Its
     * descendants are named after the model's DEF names (VRML97, X3D) or node names (glTF).
     */
    public Node root() {
        return root;
    }

    /**
     * Moves the agent in a straight line from {@code from} to {@code to}, starting at simulated
     * time {@code startTime} and arriving {@code duration} seconds later, as the paper's viewer
     * did on a MoveMessage. A model with the paper's nodes (a PositionInterpolator
     * {@code <Name>Mover} and a TimeSensor {@code <Name>TSMover}, or {@code <Name>TSMove} as in
     * the paper's Figure 5, with a ROUTE from the sensor's {@code fraction_changed} to the
     * mover's {@code set_fraction}) has the mover's key values set to {@code [from, to]} and the
     * sensor started for {@code duration}; its own ROUTEs then move it. Any other model has its
     * Transform (or glTF node) named after the agent moved, or its root if there is none. A new
     * move replaces one in progress. A duration of zero jumps at {@code startTime}.
     *
     * @throws ModelException if a coordinate or time is not finite or the duration is negative
     */
    public void moveTo(Vector3f from, Vector3f to, double startTime, double duration)
            throws ModelException {
        requireFinite("from", from);
        requireFinite("to", to);
        if (!Double.isFinite(startTime)) {
            throw bad("moveTo startTime must be finite but is " + startTime);
        }
        if (!Double.isFinite(duration) || duration < 0) {
            throw bad("moveTo duration must be zero or more seconds but is " + duration);
        }
        rig.moveTo(from, to, startTime, duration);
    }

    /**
     * Turns the whole agent: sets the rotation of its Transform (or node) named after the agent,
     * or of the root if there is none.
     *
     * @throws ModelException if the axis or angle is not finite
     */
    public void setRotation(Vector3f axis, float angle) throws ModelException {
        rig.setRotation(rotation("setRotation", axis, angle));
    }

    /**
     * Sets the rotation of a joint: a DEF'd Transform of a VRML97 or X3D model, or a named node
     * (or skeleton joint) of a glTF model. A zero axis means no rotation.
     *
     * @throws ModelException if the model has no such joint (the message lists those it has),
     *                        or the axis or angle is not finite
     */
    public void setJointRotation(String joint, Vector3f axis, float angle)
            throws ModelException {
        Objects.requireNonNull(joint, "joint");
        rig.setJointRotation(joint, rotation("setJointRotation " + joint, axis, angle));
    }

    /**
     * Starts an animation now (at the time of the last {@link #update}): a DEF'd TimeSensor of
     * a VRML97 or X3D model, enabled and started with the given loop mode, or a glTF clip.
     *
     * @throws ModelException if the model has no animation of that name
     */
    public void startAnimation(String name, boolean loop) throws ModelException {
        Objects.requireNonNull(name, "name");
        rig.startAnimation(name, loop, time());
    }

    /**
     * Stops an animation: disables the TimeSensor, or stops the glTF clip if it is playing. The
     * pose stays where the animation left it.
     *
     * @throws ModelException if the model has no animation of that name
     */
    public void stopAnimation(String name) throws ModelException {
        Objects.requireNonNull(name, "name");
        rig.stopAnimation(name);
    }

    /**
     * Scales the model to {@code height} metres and stands it on y = 0 centred on its origin, as
     * authored bounds have it ({@link Fitting}); call it once, before the model is shown. Moves and
     * turns are unaffected: they go to the node above the fitted one.
     *
     * @throws ModelException if the height is not a positive finite number
     */
    public void fitToHeight(double height) throws ModelException {
        if (!(height > 0) || !Double.isFinite(height)) {
            throw bad("fitToHeight height must be a positive number of metres but is " + height);
        }
        Fitting.fit(root, agentName, (float) height);
    }

    /** Whether the model has a node of that name: a DEF name, or a glTF node or joint name. */
    public boolean hasNode(String name) {
        return rig.hasNode(name);
    }

    /** The names {@link #setJointRotation} accepts. */
    public Set<String> jointNames() {
        return rig.jointNames();
    }

    /** The DEF names of the model's TimeSensors (empty for glTF). */
    public Set<String> timeSensorNames() {
        return rig.timeSensorNames();
    }

    /** The names {@link #startAnimation} accepts: TimeSensors, or glTF clips. */
    public Set<String> animationNames() {
        return rig.animationNames();
    }

    /**
     * Advances the model to simulated time {@code time}, in seconds: steps the event graph
     * (TimeSensors, interpolators, ROUTEs), glTF clips and moves. Call it once a frame with a
     * non-decreasing time; a time earlier than the last one (or NaN) is ignored.
     */
    public void update(double time) {
        if (Double.isNaN(time) || time < now) {
            return;
        }
        double elapsed = now == Double.NEGATIVE_INFINITY ? 0 : time - now;
        now = time;
        rig.update(time, elapsed);
    }

    /** The simulated time of the last {@link #update}, or 0 before the first. */
    public double time() {
        return now == Double.NEGATIVE_INFINITY ? 0 : now;
    }

    @Override
    public String toString() {
        return "BodyModel[" + agentName + ", " + (format == null ? "placeholder" : format) + "]";
    }

    private static Quaternion rotation(String what, Vector3f axis, float angle)
            throws ModelException {
        requireFinite(what + " axis", axis);
        if (!Float.isFinite(angle)) {
            throw bad(what + " angle must be finite but is " + angle);
        }
        return Rotations.fromAxisAngle(axis.x, axis.y, axis.z, angle);
    }

    private static void requireFinite(String what, Vector3f v) throws ModelException {
        Objects.requireNonNull(v, what);
        if (!Vector3f.isValidVector(v)) {
            throw bad(what + " must be finite but is " + v);
        }
    }

    private static ModelException bad(String message) {
        return new ModelException(Kind.BAD_VALUE, message);
    }
}
