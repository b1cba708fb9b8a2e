package io.orchard.protocol.message;

/**
 * A server message that answers one client message: its {@code seq} is the one the client sent.
 */
public sealed interface Reply extends ServerMessage permits ActionResultMessage, ErrorMessage, GraspResultMessage, RegisteredMessage, WelcomeMessage {

    /** The sequence number of the client message this answers (0 for an error that answers none). */
    long seq();
}
