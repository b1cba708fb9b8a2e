package io.orchard.agents.zoo;

import io.orchard.agents.behaviour.Harvester;
import io.orchard.agents.behaviour.Motor;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Joint poses held for a while and then released to neutral, for the gestures of the zoo's agents.
 * Hinges turn about x, as the models' conventions have it (models/README.md).
 */
final class Pose {

    private final Motor motor;
    private final Map<String, Double> held = new LinkedHashMap<>();
    private double releaseAt = Double.POSITIVE_INFINITY;

    /** The joints of the zoo's two-armed, two-legged figures (the Dwarf's and Guppy's models), which gestures turn. */
    static String[] figureJoints() {
        return new String[] {"Neck", "LeftShoulder", "LeftElbow", "RightShoulder", "RightElbow", "LeftHip", "LeftKnee",
            "RightHip", "RightKnee"};
    }

    Pose(Motor motor) {
        this.motor = motor;
    }

    /** A rotation of {@code angle} about x. */
    static Rotation pitch(double angle) {
        return new Rotation(new Vec3(1, 0, 0), angle);
    }

    /** Turns a joint about x and holds it until {@link #release()} or the hold runs out. */
    Pose set(String joint, double angle) {
        motor.setJoint(joint, pitch(angle));
        held.put(joint, angle);
        return this;
    }

    /** Turns a joint about any axis and holds it. */
    Pose set(String joint, Rotation rotation) {
        motor.setJoint(joint, rotation);
        held.put(joint, rotation.angle());
        return this;
    }

    /** Releases the pose {@code seconds} from now. */
    void holdFor(double seconds) {
        releaseAt = motor.time() + seconds;
    }

    /** Call once a tick: releases the pose when its time has come. */
    void update() {
        if (motor.time() >= releaseAt) {
            release();
        }
    }

    /** Turns every held joint back to neutral. */
    void release() {
        for (String joint : held.keySet()) {
            motor.setJoint(joint, pitch(0));
        }
        held.clear();
        releaseAt = Double.POSITIVE_INFINITY;
    }

    /**
     * How an agent with arms reaches for a fruit: one lower than {@code crouchBelow} is taken with
     * the body's grasp animation (only the animation can crouch), a higher one by raising both
     * shoulders to the fruit's height for a second. {@code raised} adds what else the agent does
     * with its arms up.
     */
    Harvester.Gesture armsReach(double crouchBelow, Runnable crouch, double shoulderHeight, double armLength,
                                Consumer<Pose> raised) {
        return fruit -> {
            if (fruit.height() < crouchBelow) {
                crouch.run();
                return;
            }
            double angle = armAngle(shoulderHeight, armLength, fruit.height());
            set("LeftShoulder", angle).set("RightShoulder", angle);
            raised.accept(this);
            holdFor(1);
        };
    }

    /** The shoulder angle that brings a hand hanging {@code armLength} below a shoulder at {@code shoulderHeight} to {@code height}. */
    static double armAngle(double shoulderHeight, double armLength, double height) {
        double cos = (shoulderHeight - height) / armLength;
        return Math.acos(Math.max(-1, Math.min(1, cos)));
    }
}
