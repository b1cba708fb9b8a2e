package io.orchard.server.net;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The places for lines longer than an ordinary message (a registration carrying a model, up to
 * 8 MiB): so many may be received at once, so that a crowd of clients each sending one cannot make
 * the server buffer thousands of them. A client beyond waits, not reading, until a place frees; it
 * is handed the place in the order it asked. Shared by every channel; safe from any thread.
 */
final class LineSlots {

    /** One who waits for a place. */
    interface Waiter {
        /** Called, on any thread, when the place is handed over. */
        void granted();
    }

    private final int capacity;
    private int taken;
    private final Deque<Waiter> waiting = new ArrayDeque<>();

    LineSlots(int capacity) {
        this.capacity = capacity;
    }

    /** Takes a place now and says so, or queues the waiter to be {@linkplain Waiter#granted granted} one later. */
    boolean take(Waiter waiter) {
        synchronized (this) {
            if (taken < capacity) {
                taken++;
                return true;
            }
            waiting.addLast(waiter);
            return false;
        }
    }

    /** Gives a place back, handing it to the longest waiter if there is one. */
    void give() {
        Waiter next;
        synchronized (this) {
            next = waiting.pollFirst();
            if (next == null) {
                taken--;
                return;
            }
        }
        next.granted();
    }

    /** The waiter no longer waits (its connection closed). */
    synchronized void withdraw(Waiter waiter) {
        waiting.remove(waiter);
    }

    /** Places taken now. */
    synchronized int taken() {
        return taken;
    }
}
