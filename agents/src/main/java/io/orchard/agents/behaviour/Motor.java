package io.orchard.agents.behaviour;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Rotation;

/**
 * What a behaviour needs of the agent it drives: where it is, and the paper's actions. The agent's
 * controller implements it; every action is sent during the current tick and takes effect at its
 * end.
 */
public interface Motor {

    /** Where the agent stood at the start of this tick (its latest perception). */
    Point2 position();

    /** The agent's heading, including a turn sent during this tick. */
    double heading();

    /** The current tick. */
    long tick();

    /** Simulated seconds since the game started, at the start of this tick. */
    double time();

    /** The body in force, as the server confirmed it. */
    Body body();

    /**
     * Walks in a straight line from here to {@code to}, replacing any move under way.
     *
     * @param face whether to turn to face the way first (an agent that walks in any direction
     *             need not)
     */
    void moveTo(Point2 to, boolean face);

    /** Turns on the spot to this heading. */
    void turnTo(double heading);

    /** Stops walking where the agent stands. */
    void halt();

    /** Whether a move is under way: accepted (or not yet answered) and not yet over. */
    boolean walking();

    /** The latest move; null before the first. */
    @Nullable MoveStatus lastMove();

    /** Asks to grasp a fruit (the server decides whether it is in reach). */
    void grasp(String fruitId);

    /** The latest grasp; null before the first. */
    @Nullable GraspStatus lastGrasp();

    /** Turns a registered joint of the agent's model. */
    void setJoint(String joint, Rotation rotation);

    /** Starts a registered animation. */
    void startAnimation(String timeSensor, boolean loop);

    /** Stops a registered animation. */
    void stopAnimation(String timeSensor);

    /**
     * Plays a registered animation once, for {@code seconds}: the walk animation (which drives
     * the same joints) pauses meanwhile and resumes after it if the agent still walks.
     */
    void play(String timeSensor, double seconds);

    /** Says something to people (every client hears it). */
    void say(String text);
}
