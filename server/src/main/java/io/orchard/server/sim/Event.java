package io.orchard.server.sim;

import io.orchard.protocol.message.ClientMessage;

/** Something a client did, queued for the simulation's thread. */
sealed interface Event {

    ClientSession session();

    record Connected(ClientSession session) implements Event {}

    record Received(ClientSession session, ClientMessage message) implements Event {}

    record Disconnected(ClientSession session, String reason) implements Event {}

    /** Work for the simulation's thread from elsewhere in the program (a console command). */
    record Task(Runnable action) implements Event {
        @Override
        public ClientSession session() {
            return null;
        }
    }
}
