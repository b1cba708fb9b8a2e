package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Role;
import java.util.List;

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
 * @param reads the forms of the server's lines the client reads besides the ordinary ones (version 2), by
 *              name ({@code io.orchard.protocol.value.Form}); names the server does not know are ignored.
 *              Absent: the ordinary lines only
 */
public record HelloMessage(long seq,
                           int protocolVersion,
                           Role role,
                           String client,
                           @Nullable String token,
                           @Nullable String operatorToken,
                           @Nullable List<String> reads) implements ClientMessage {

    /** The most form names a hello may carry. */
    public static final int MAX_FORMS = 16;

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
        if (reads != null) {
            reads = Checks.list(reads, "reads");
            if (reads.size() > MAX_FORMS) {
                throw new IllegalArgumentException("reads must name at most " + MAX_FORMS + " forms, named "
                        + reads.size());
            }
            for (int i = 0; i < reads.size(); i++) {
                Checks.name(reads.get(i), "reads[" + i + "]");
            }
        }
    }

    /** A hello that asks for no other form than the ordinary. */
    public HelloMessage(long seq, int protocolVersion, Role role, String client, String token, String operatorToken) {
        this(seq, protocolVersion, role, client, token, operatorToken, null);
    }

    /** A hello without an operator token. */
    public HelloMessage(long seq, int protocolVersion, Role role, String client, String token) {
        this(seq, protocolVersion, role, client, token, null, null);
    }
}
