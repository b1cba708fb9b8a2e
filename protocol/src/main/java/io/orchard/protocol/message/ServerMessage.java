package io.orchard.protocol.message;

/**
 * A message from the server to a client: replies ({@link Reply}), perceptions, news of the game,
 * and for viewers every change of the world.
 */
public sealed interface ServerMessage extends Message permits Reply,
        ActionResultMessage,
        AgentAddedMessage,
        AgentMovedMessage,
        AgentRemovedMessage,
        AgentRotatedMessage,
        AnimationStartedMessage,
        AnimationStoppedMessage,
        CastlePerceptionMessage,
        ErrorMessage,
        FruitEatenMessage,
        FruitRemovedMessage,
        GameOverMessage,
        GameStartedMessage,
        GraspResultMessage,
        InstructionMessage,
        JointRotatedMessage,
        LandmarkPerceptionMessage,
        LeanPerceptionMessage,
        NewGameMessage,
        PerceptionMessage,
        RegisteredMessage,
        SayMessage,
        ScoreUpdateMessage,
        TickMessage,
        WelcomeMessage,
        WorldSnapshotMessage {
}
