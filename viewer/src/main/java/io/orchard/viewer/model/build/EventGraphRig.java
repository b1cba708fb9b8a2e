package io.orchard.viewer.model.build;

import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.Rig;
import io.orchard.viewer.model.event.LiveInterpolator;
import io.orchard.viewer.model.event.LiveTimeSensor;
import io.orchard.viewer.model.event.LiveTransform;
import java.util.Set;

/**
 * The rig of a VRML97 or X3D model: moves go through the paper's Mover and TSMover nodes when the
 * model has them (with the ROUTE from the sensor to the mover), otherwise straight to the
 * Transform named after the agent, or to the model's root; joints are its DEF'd Transforms and
 * animations its DEF'd TimeSensors.
 */
public final class EventGraphRig implements Rig {

    /** A zero-length move still needs a positive cycle; this one ends within one frame. */
    private static final double SHORTEST_CYCLE = 1e-6;

    private final String agentName;
    private final Node root;
    private final SceneBuilder.Result scene;
    private final LiveTransform agentTransform;
    private final LiveInterpolator mover;
    private final LiveTimeSensor moverClock;
    private MoveTween tween;

    /** Finds the Transform named after the agent and, if they exist and are ROUTEd, its Mover and TSMover. */
    public EventGraphRig(String agentName, SceneBuilder.Result scene) {
        this.agentName = agentName;
        this.root = scene.root();
        this.scene = scene;
        this.agentTransform = scene.transforms().get(agentName);
        LiveInterpolator candidate = scene.interpolators().get(agentName + "Mover");
        LiveTimeSensor clock = scene.sensors().get(agentName + "TSMover");
        if (clock == null) {
            clock = scene.sensors().get(agentName + "TSMove"); // the spelling of Figure 5
        }
        boolean usable = candidate != null && clock != null
                && candidate.kind() == LiveInterpolator.Kind.POSITION
                && scene.graph().isRouted(clock, "fraction_changed", candidate, "set_fraction");
        this.mover = usable ? candidate : null;
        this.moverClock = usable ? clock : null;
    }

    @Override
    public void moveTo(Vector3f from, Vector3f to, double startTime, double duration) {
        if (mover != null) {
            tween = null;
            Vector3f start = duration > 0 ? from : to;
            mover.setKeys(new float[] {0, 1},
                    new float[] {start.x, start.y, start.z, to.x, to.y, to.z});
            moverClock.start(startTime, false, Math.max(duration, SHORTEST_CYCLE));
            return;
        }
        tween = new MoveTween(from, to, startTime, duration, agentTransform != null
                ? agentTransform::setTranslation : root::setLocalTranslation);
    }

    @Override
    public void setRotation(Quaternion rotation) {
        if (agentTransform != null) {
            agentTransform.setRotation(rotation);
        } else {
            root.setLocalRotation(rotation);
        }
    }

    @Override
    public void setJointRotation(String joint, Quaternion rotation) throws ModelException {
        LiveTransform transform = scene.transforms().get(joint);
        if (transform == null) {
            throw UnknownName.error("joint (DEF'd Transform)", joint, jointNames());
        }
        transform.setRotation(rotation);
    }

    @Override
    public void startAnimation(String name, boolean loop, double now) throws ModelException {
        LiveTimeSensor sensor = sensor(name);
        sensor.start(now, loop, sensor.cycleInterval());
    }

    @Override
    public void stopAnimation(String name) throws ModelException {
        sensor(name).stop();
    }

    private LiveTimeSensor sensor(String name) throws ModelException {
        LiveTimeSensor sensor = scene.sensors().get(name);
        if (sensor == null) {
            throw UnknownName.error("animation (DEF'd TimeSensor)", name, timeSensorNames());
        }
        return sensor;
    }

    @Override
    public boolean hasNode(String name) {
        return scene.defNames().contains(name);
    }

    @Override
    public Set<String> jointNames() {
        return Set.copyOf(scene.transforms().keySet());
    }

    @Override
    public Set<String> timeSensorNames() {
        return Set.copyOf(scene.sensors().keySet());
    }

    @Override
    public Set<String> animationNames() {
        return timeSensorNames();
    }

    @Override
    public void update(double time, double elapsed) {
        scene.graph().step(time);
        if (tween != null) {
            tween.apply(time);
            if (tween.isDone()) {
                tween = null;
            }
        }
    }

    @Override
    public String toString() {
        return "EventGraphRig[" + agentName + "]";
    }
}
