package io.orchard.protocol.message;

/**
 * A message about one agent in the world, the one {@link #agent()} names. From a client it is one
 * of that agent's own actions (a move, a turn, a grasp, a registered joint, its leaving), which only
 * the connection that registered the agent may send; from the server it is news of that agent for
 * viewers (it walked, turned, moved a joint, started or stopped an animation, left). {@link SayMessage}
 * is both: what the agent says, and the news of it.
 *
 * <p>A program that keeps agents by name finds the agent once through this interface and then looks
 * at what the message says of it. Messages that merely mention an agent are not among these: a
 * result, a perception, a fruit eaten (it is about the fruit), an instruction (anyone may send one to
 * any agent).
 */
public sealed interface AgentMessage permits AgentMovedMessage,
        AgentRemovedMessage,
        AgentRotatedMessage,
        AnimationStartedMessage,
        AnimationStoppedMessage,
        GraspRequestMessage,
        JointRotatedMessage,
        MoveMessage,
        PerceptionRequestMessage,
        RegisterJointMessage,
        RegisterTimeSensorMessage,
        SayMessage,
        SetJointRotationMessage,
        SetRotationMessage,
        StartAnimationMessage,
        StopAnimationMessage,
        UnregisterMessage {

    /** The name of the agent the message is about. */
    String agent();
}
