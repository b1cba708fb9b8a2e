package io.orchard.server;

import java.io.IOException;
import java.net.InetSocketAddress;

/**
 * The browser viewer, as the server finds it: the web module ({@code io.orchard:web}) provides it
 * through {@link java.util.ServiceLoader}, so that the server runs without it and serves a page only
 * when {@link WorldServer.Builder#httpPort(int)} asks for one and the module is on the class path.
 */
public interface WebFrontEnd {

    /**
     * Starts serving the page on {@code http}; its WebSocket speaks the protocol to the game server
     * listening on {@code game}, as any viewer does.
     *
     * @throws IOException when {@code http} cannot be bound, saying why
     */
    Serving serve(InetSocketAddress http, InetSocketAddress game) throws IOException;

    /** A page being served, until closed. */
    interface Serving extends AutoCloseable {

        /** Where the page is served (the real port when asked for port 0). */
        InetSocketAddress address();

        /** Stops serving, closing every browser's connection. */
        @Override
        void close();
    }
}
