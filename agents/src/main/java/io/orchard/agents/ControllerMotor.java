package io.orchard.agents;

import io.orchard.agents.behaviour.GraspStatus;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.MoveStatus;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Rotation;

/** A controller's actions and state as behaviours see them: each call goes to the controller. */
final class ControllerMotor implements Motor {

    private final AgentController controller;

    ControllerMotor(AgentController controller) {
        this.controller = controller;
    }

    @Override
    public Point2 position() {
        return controller.position();
    }

    @Override
    public double heading() {
        return controller.heading();
    }

    @Override
    public long tick() {
        return controller.tick();
    }

    @Override
    public double time() {
        return controller.time();
    }

    @Override
    public Body body() {
        return controller.bodyInForce();
    }

    @Override
    public void moveTo(Point2 to, boolean face) {
        if (face) {
            controller.face(to);
        }
        controller.moveTo(to);
    }

    @Override
    public void turnTo(double heading) {
        controller.turnTo(heading);
    }

    @Override
    public void halt() {
        controller.halt();
    }

    @Override
    public boolean walking() {
        return controller.walking();
    }

    @Override
    public MoveStatus lastMove() {
        return controller.lastMove();
    }

    @Override
    public void grasp(String fruitId) {
        controller.grasp(fruitId);
    }

    @Override
    public GraspStatus lastGrasp() {
        return controller.lastGrasp();
    }

    @Override
    public void setJoint(String joint, Rotation rotation) {
        controller.setJoint(joint, rotation);
    }

    @Override
    public void startAnimation(String timeSensor, boolean loop) {
        controller.startAnimation(timeSensor, loop);
    }

    @Override
    public void stopAnimation(String timeSensor) {
        controller.stopAnimation(timeSensor);
    }

    @Override
    public void play(String timeSensor, double seconds) {
        controller.play(timeSensor, seconds);
    }

    @Override
    public void say(String text) {
        controller.say(text);
    }
}
