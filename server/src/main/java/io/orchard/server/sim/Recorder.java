package io.orchard.server.sim;

import io.orchard.protocol.message.Message;

/**
 * Receives every message the server accepted and every message it sent, in order, to keep a record
 * of the game. Called on the simulation's thread.
 */
public interface Recorder extends AutoCloseable {

    /** Records nothing. */
    Recorder NONE = new Recorder() {
        @Override
        public void accepted(long tick, double time, long session, Message message) {}

        @Override
        public void sent(long tick, double time, Audience to, long session, Message message) {}

        @Override
        public void close() {}
    };

    /** Who a sent message went to. */
    enum Audience {
        /** One client, named by its session number. */
        CLIENT,
        /** Every client. */
        ALL,
        /** Every viewer. */
        VIEWERS,
        /** Every agent client. */
        AGENTS
    }

    /** A client message the simulation accepted (decoded, and from a client allowed to send it). */
    void accepted(long tick, double time, long session, Message message);

    /** A message the simulation sent; {@code session} is 0 unless {@code to} is {@link Audience#CLIENT}. */
    void sent(long tick, double time, Audience to, long session, Message message);

    /** Writes out what was recorded so far; called at the end of every half tick. */
    default void flush() {}

    @Override
    void close();
}
