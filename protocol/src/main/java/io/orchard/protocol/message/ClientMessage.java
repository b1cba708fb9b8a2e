package io.orchard.protocol.message;

/**
 * A message from a client (an agent control client or a viewer) to the server. Each carries a
 * client-chosen {@code seq}; the server's reply or error carries the same number back, so a client
 * can match answers to requests. Numbers need not be consecutive; increasing is conventional.
 */
public sealed interface ClientMessage extends Message permits EndTurnMessage,
        GameControlMessage,
        GraspRequestMessage,
        HelloMessage,
        InstructionMessage,
        KeepAliveMessage,
        MoveMessage,
        PerceptionRequestMessage,
        RegisterJointMessage,
        RegisterMessage,
        RegisterTimeSensorMessage,
        SayMessage,
        SetJointRotationMessage,
        SetRotationMessage,
        StartAnimationMessage,
        StopAnimationMessage,
        UnregisterMessage {

    /** The client-chosen sequence number, 0 or more. */
    long seq();
}
