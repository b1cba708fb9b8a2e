package io.orchard.server.net;

import io.netty.channel.Channel;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The connections that have not said {@code Hello} yet, oldest first, at most so many: when one
 * more arrives, the one that has waited longest is handed back to be closed. A flood of sockets
 * that never speak then costs a bounded number of connections for a few seconds each, and never
 * takes the places of clients that do speak (which say {@code Hello} as they connect). Shared by
 * every channel; safe from any thread.
 */
final class HelloQueue {

    private final int max;
    private final Deque<Channel> waiting = new ArrayDeque<>();

    HelloQueue(int max) {
        this.max = max;
    }

    /** Adds a new connection; returns the connection to close to make room for it, or null. */
    synchronized Channel arrived(Channel channel) {
        waiting.addLast(channel);
        return waiting.size() > max ? waiting.pollFirst() : null;
    }

    /** The connection said {@code Hello}, or closed. */
    synchronized void left(Channel channel) {
        waiting.remove(channel);
    }

    /** Connections waiting now. */
    synchronized int size() {
        return waiting.size();
    }

    /** The most that may wait at once. */
    int max() {
        return max;
    }
}
