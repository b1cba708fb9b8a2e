package io.orchard.viewer.world;

import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * One agent as the viewer knows it: its body and model from {@code AgentAdded}, then its last
 * move, its orientation, the rotation of each joint that was turned and the animations that run.
 * Together these are enough to pose a freshly loaded model exactly as one that has followed every
 * message. Changed only by {@link WorldMirror}; read on the same thread.
 */
public final class AgentView {

    private final AgentState added;
    private Vec3 position;
    private Motion motion;
    private Rotation rotation;
    private double heading;
    private final Map<String, Rotation> joints = new LinkedHashMap<>();
    private final Map<String, RunningAnimation> animations = new LinkedHashMap<>();

    AgentView(AgentState added) {
        this.added = added;
        this.position = added.position();
        this.rotation = Rotation.heading(added.heading());
        this.heading = added.heading();
    }

    /** The agent's name. */
    public String name() {
        return added.name();
    }

    /** Its body in force: radius, height, speed, gripper and sight. */
    public Body body() {
        return added.body();
    }

    /** The model it registered with; empty when it sent none. */
    public Optional<ModelSpec> model() {
        return Optional.ofNullable(added.model());
    }

    /** The joints its controller registered. */
    public List<String> registeredJoints() {
        return added.joints();
    }

    /** The time sensors its controller registered. */
    public List<String> registeredTimeSensors() {
        return added.timeSensors();
    }

    /** Where it stands at simulated time {@code time}, following its last move. */
    public Vec3 positionAt(double time) {
        return motion == null ? position : motion.at(time);
    }

    /** Its last move, or null when it has not moved since the viewer heard of it. */
    public Motion motion() {
        return motion;
    }

    /** Its orientation as last sent: about the up axis for a heading. */
    public Rotation rotation() {
        return rotation;
    }

    /**
     * Its heading in radians (0 faces north, -z; positive turns left). An orientation that is
     * not about the up axis keeps the heading it had.
     */
    public double heading() {
        return heading;
    }

    /** The last rotation of each joint that was turned, in the order they were first turned. */
    public Map<String, Rotation> jointRotations() {
        return Collections.unmodifiableMap(joints);
    }

    /** The animations started and not stopped, in the order they started. */
    public List<RunningAnimation> runningAnimations() {
        return List.copyOf(animations.values());
    }

    void moved(Motion next) {
        this.position = next.from();
        this.motion = next;
    }

    void rotated(Rotation next) {
        this.rotation = next;
        if (next.isAboutUpAxis()) {
            this.heading = next.headingAngle();
        }
    }

    void jointRotated(String joint, Rotation next) {
        joints.put(joint, next);
    }

    void animationStarted(RunningAnimation animation) {
        animations.remove(animation.name());
        animations.put(animation.name(), animation);
    }

    void animationStopped(String name) {
        animations.remove(name);
    }

    @Override
    public String toString() {
        return "AgentView[" + name() + "]";
    }
}
