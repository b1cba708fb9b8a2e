package io.orchard.web;

import io.orchard.server.WebFrontEnd;
import java.io.IOException;
import java.net.InetSocketAddress;

/**
 * The browser viewer: serves a three.js page whose script watches the game and instructs its agents
 * over a WebSocket, relayed line for line to the game server's TCP port, so that the page is a
 * viewer like any other. The server finds it through {@link java.util.ServiceLoader} when asked for
 * an HTTP port ({@code WorldServer.Builder.httpPort}, {@code ./orchard server --http-port}).
 */
public final class WebViewer implements WebFrontEnd {

    /** For {@link java.util.ServiceLoader}. */
    public WebViewer() {
        // nothing to set up before serve
    }

    @Override
    public Serving serve(InetSocketAddress http, InetSocketAddress game) throws IOException {
        return PageServer.start(http, game, Site.fromJar());
    }
}
