package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Role;

/**
 * The first line a client sends: the protocol version it speaks and what it is. The server answers
 * with {@link WelcomeMessage}, or with an {@link ErrorMessage} ({@code version_mismatch},
 * {@code unauthorized}) and closes the connection.
 *
 * @param seq client-chosen sequence number, echoed in the reply
 * @param protocolVersion the protocol version the client speaks (see {@code ProtocolVersion})
 * @param role agent control client or viewer
 * @param client a free name for the client program, for logs
 * @param token the shared secret, when the server requires one
 * @param operatorToken the operator's secret (version 2): a client that presents the one the server
 *                      was given may start, pause and resume the game with {@link GameControlMessage}
 */
public record HelloMessage(long seq,
                           int protocolVersion,
                           Role role,
                           String client,
                           @Nullable String token,
                           @Nullable String operatorToken) implements ClientMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public HelloMessage {
        Checks.nonNegative(seq, "seq");
        if (protocolVersion <= 0) {
            throw new IllegalArgumentException("protocolVersion must be greater than 0, was " + protocolVersion);
        }
        Checks.present(role, "role");
        Checks.text(client, "client");
        Checks.optionalText(token, "token");
        Checks.optionalText(operatorToken, "operatorToken");
    }

    /** A hello without an operator token. */
    public HelloMessage(long seq, int protocolVersion, Role role, String client, String token) {
        this(seq, protocolVersion, role, client, token, null);
    }
}
