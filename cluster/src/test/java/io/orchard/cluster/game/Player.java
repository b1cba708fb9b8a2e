package io.orchard.cluster.game;

import io.orchard.protocol.message.ClientMessage;
import java.util.List;

/** A deterministic agent of a test game, with its in-memory session. */
interface Player {

    /** Its session, on which it reads what it is sent. */
    TestSession session();

    /** Its registration. */
    List<ClientMessage> register();

    /** After its registration: its setup, ending with its setup turn. */
    List<ClientMessage> setUp();

    /** Its actions of {@code tick}, ending its turn, from what it was sent since. */
    List<ClientMessage> act(long tick);
}
