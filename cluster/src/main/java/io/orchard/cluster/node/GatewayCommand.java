package io.orchard.cluster.node;

import java.util.List;

/** What the tick tells a node's gateway ({@link Gateway}): lines for its clients, and the clock. */
public sealed interface GatewayCommand extends ClusterMessage {

    /** Lines of the protocol for one client, in order, then a flush. */
    record Deliver(long session, List<String> lines) implements GatewayCommand {}

    /** A last line for a client, and its connection closes. */
    record Close(long session, String line) implements GatewayCommand {}

    /** Where the game is, for the welcomes of clients that connect now. */
    record Clock(long tick, String phase) implements GatewayCommand {}
}
