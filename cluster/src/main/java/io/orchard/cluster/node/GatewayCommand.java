package io.orchard.cluster.node;

import java.util.List;

/** What the tick tells a node's gateway ({@link Gateway}): lines for its clients, the clock, a rollback. */
public sealed interface GatewayCommand extends ClusterMessage {

    /** Lines of the protocol for one client, in order, then a flush. */
    record Deliver(long session, List<String> lines) implements GatewayCommand {}

    /** A last line for a client, and its connection closes. */
    record Close(long session, String line) implements GatewayCommand {}

    /**
     * Where the game is, for the welcomes of clients that connect now: the tick's epoch (its number
     * of new starts since the cluster began), the tick and the phase.
     */
    record Clock(long epoch, long tick, String phase) implements GatewayCommand {}

    /**
     * The tick started the game again (a node was lost, or the tick moved to another node): every
     * client connected now gets this last line and its connection closes; its controller comes back
     * with its resume tokens, to any node.
     */
    record Rollback(long epoch, String line) implements GatewayCommand {}
}
