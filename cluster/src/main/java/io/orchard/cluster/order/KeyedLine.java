package io.orchard.cluster.order;

import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.server.sim.MissedTurn;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Recorder.Audience;

/**
 * One line a part of the world said, with its place in the tick: a message it applied ({@code to}
 * null), sent ({@code to} its audience) or a missed turn; and, for a message sent to one client, the
 * client and the message as sent (a recording leaves secrets out, the client gets them).
 *
 * @param key     its place
 * @param tick    the tick it is stamped with
 * @param time    the simulated time it is stamped with
 * @param to      the audience of a message sent; null for one applied or a missed turn
 * @param client  the label of the client it came from or went to, as the recording names it
 * @param message the message as recorded; null for a missed turn
 * @param missed  the missed turn, or null
 * @param target  the client a message sent to one client goes to; null otherwise
 * @param sent    the message as that client gets it; null unless {@code target} is set
 */
public record KeyedLine(LineKey key, long tick, double time, Audience to, String client, Message message,
                        MissedTurn missed, SessionRef target, ServerMessage sent) {

    /** This line going to {@code session} as {@code message}. */
    KeyedLine deliveredTo(SessionRef session, ServerMessage message) {
        return new KeyedLine(key, tick, time, to, client, this.message, missed, session, message);
    }

    /** Writes this line to a recording. */
    public void writeTo(Recorder recorder) {
        if (missed != null) {
            recorder.missed(tick, time, client, missed);
        } else if (to == null) {
            recorder.accepted(tick, time, client, message);
        } else {
            recorder.sent(tick, time, to, client, message);
        }
    }
}
