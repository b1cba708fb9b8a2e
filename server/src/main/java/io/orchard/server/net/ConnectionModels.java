package io.orchard.server.net;

import java.util.ArrayList;
import java.util.List;

/**
 * The different models one connection has registered, and their decoded bytes: what the cap on a
 * connection's models counts. Registering the same model again costs nothing. Holding the texts
 * keeps them in the {@link ModelStore}'s count for as long as the connection is open, which the cap
 * bounds. One per connection, used under the store's lock.
 */
final class ConnectionModels {

    private final List<String> texts = new ArrayList<>();
    private long bytes;

    boolean has(String text) {
        for (String mine : texts) {
            if (mine == text) {
                return true;
            }
        }
        return false;
    }

    void add(String text, int size) {
        texts.add(text);
        bytes += size;
    }

    long bytes() {
        return bytes;
    }
}
