package io.orchard.viewer.model.build;

import com.jme3.math.Vector3f;
import java.util.function.Consumer;

/**
 * A straight-line move from one point to another between two simulated times: what the paper's
 * Mover/TSMover pair does, for models that do not define one. Before the start it leaves the
 * target alone; after the end it places it at the destination once and is done.
 */
final class MoveTween {

    private final Vector3f from;
    private final Vector3f to;
    private final double startTime;
    private final double duration;
    private final Consumer<Vector3f> target;
    private boolean done;

    MoveTween(Vector3f from, Vector3f to, double startTime, double duration,
              Consumer<Vector3f> target) {
        this.from = from.clone();
        this.to = to.clone();
        this.startTime = startTime;
        this.duration = duration;
        this.target = target;
    }

    boolean isDone() {
        return done;
    }

    void apply(double now) {
        if (done || now < startTime) {
            return;
        }
        double fraction = duration > 0 ? Math.min(1.0, (now - startTime) / duration) : 1.0;
        target.accept(new Vector3f().interpolateLocal(from, to, (float) fraction));
        done = fraction >= 1.0;
    }
}
