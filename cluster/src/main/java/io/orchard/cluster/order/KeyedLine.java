package io.orchard.cluster.order;

import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.server.sim.MissedTurn;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Recorder.Audience;

/**
 * One line a part of the world said, with its place in the tick: a message it applied ({@code to}
 * null), sent ({@code to} its audience) or a missed turn; and, for a message sent to one client, the
 * client and the message as sent (a recording leaves secrets out, the client gets them). Two kinds of
 * line are not recorded: a message a client is sent only to catch up with the game ({@code target}
 * and {@code sent} alone), and a client joining the audiences of broadcasts ({@code target} alone).
 *
 * @param key     its place
 * @param tick    the tick it is stamped with
 * @param time    the simulated time it is stamped with
 * @param to      the audience of a message sent; null for one applied or a missed turn
 * @param client  the label of the client it came from or went to, as the recording names it
 * @param message the message as recorded; null for a missed turn and for lines not recorded
 * @param missed  the missed turn, or null
 * @param target  the client a message sent to one client goes to, or who joins; null otherwise
 * @param sent    the message as that client gets it; null unless {@code target} is set
 */
public record KeyedLine(LineKey key, long tick, double time, Audience to, String client, Message message,
                        MissedTurn missed, SessionRef target, ServerMessage sent) {

    /** A message for one client that is not recorded: what it is told to catch up with the game. */
    public static KeyedLine catchUp(LineKey key, SessionRef to, ServerMessage message) {
        return new KeyedLine(key, 0, 0, null, null, null, null, to, message);
    }

    /** A client joins the audiences of broadcasts here: what comes after reaches it, what comes before does not. */
    public static KeyedLine joining(LineKey key, SessionRef client) {
        return new KeyedLine(key, 0, 0, null, null, null, null, client, null);
    }

    /** Whether the line goes into the recording. */
    public boolean recorded() {
        return message != null || missed != null;
    }

    /** Whether the line is a client joining the audiences. */
    public boolean joins() {
        return !recorded() && target != null && sent == null;
    }

    /** This line going to {@code session} as {@code message}. */
    KeyedLine deliveredTo(SessionRef session, ServerMessage message) {
        return new KeyedLine(key, tick, time, to, client, this.message, missed, session, message);
    }

    /** Writes this line to a recording, when it is one that is recorded. */
    public void writeTo(Recorder recorder) {
        if (missed != null) {
            recorder.missed(tick, time, client, missed);
        } else if (message == null) {
            return;
        } else if (to == null) {
            recorder.accepted(tick, time, client, message);
        } else {
            recorder.sent(tick, time, to, client, message);
        }
    }
}
