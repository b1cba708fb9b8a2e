package io.orchard.server.sim;

import io.orchard.protocol.message.Message;

/**
 * Receives every message the server accepted and every message it sent, in order, to keep a record
 * of the game. Called on the simulation's thread.
 *
 * <p>A client is named by a label, never by its connection number, so that the record is a function
 * of the game alone: an agent's client by the name of the first agent it registered,
 * {@code "viewer"} for a viewer, {@code "agent"} for an agent's client before its first
 * registration.
 */
public interface Recorder extends AutoCloseable {

    /** Records nothing. */
    Recorder NONE = new Recorder() {
        @Override
        public void accepted(long tick, double time, String client, Message message) {}

        @Override
        public void sent(long tick, double time, Audience to, String client, Message message) {}

        @Override
        public void close() {}
    };

    /** Who a sent message went to. */
    enum Audience {
        /** One client, named by its label. */
        CLIENT,
        /** Every client. */
        ALL,
        /** Every viewer. */
        VIEWERS,
        /** Every agent client. */
        AGENTS
    }

    /** A client message the simulation accepted (decoded, and from a client allowed to send it). */
    void accepted(long tick, double time, String client, Message message);

    /** A message the simulation sent; {@code client} is null unless {@code to} is {@link Audience#CLIENT}. */
    void sent(long tick, double time, Audience to, String client, Message message);

    /** A lockstep turn the game went on without. */
    default void missed(long tick, double time, String client, MissedTurn missed) {}

    /** Writes out what was recorded so far; called at the end of every half tick. */
    default void flush() {}

    @Override
    void close();
}
