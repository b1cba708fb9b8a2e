package io.orchard.server.net;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Form;
import io.orchard.protocol.value.Outcome;
import java.util.Set;

/**
 * The forms of lines a client reads, as its hello asked for them ({@code reads}, version 2): the
 * lean perception, one line in place of three, and with it no reply to an accepted move unless it
 * asked for those too. A version 1 client, and any that asks for nothing, gets the ordinary lines.
 *
 * @param leanPerception whether each perception goes out as one {@code LeanPerception} line
 * @param acceptedMoves  whether an accepted {@code Move} is answered with its {@code ActionResult}
 */
record ClientForms(boolean leanPerception, boolean acceptedMoves) {

    /** The ordinary lines, as every client got them before there were other forms. */
    static final ClientForms ORDINARY = new ClientForms(false, true);

    /** The forms this hello asks for; names of forms the server does not know mean nothing. */
    static ClientForms of(HelloMessage hello) {
        if (hello.protocolVersion() < 2) {
            return ORDINARY;
        }
        Set<Form> forms = Form.named(hello.reads());
        boolean lean = forms.contains(Form.LEAN_PERCEPTION);
        return new ClientForms(lean, !lean || forms.contains(Form.ACCEPTED_MOVES));
    }

    /** Whether the client gets this message at all: not an accepted move's result, if it reads without them. */
    boolean sends(ServerMessage message) {
        return acceptedMoves || !(message instanceof ActionResultMessage result
                && result.outcome() == Outcome.ACCEPTED && result.action().equals("Move"));
    }
}
